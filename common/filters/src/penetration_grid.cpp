#include "scanfilter/penetration_grid.hpp"

#include <cassert>
#include <cmath>

namespace scanfilter {

const PenetrationGrid::Tile* PenetrationGrid::findTile(std::uint64_t key) const {
  if (last_valid_ && key == last_key_) return last_tile_;
  const auto it = tiles_.find(key);
  last_key_ = key;
  last_valid_ = true;
  last_tile_ = it == tiles_.end() ? nullptr : it->second.get();
  return last_tile_;
}

int PenetrationGrid::count(CellIndex c) const {
  const Tile* tile = findTile(tileKey(c));
  return tile ? static_cast<int>(tile->counts[slot(c)]) : 0;
}

bool PenetrationGrid::holdsSurfaceBetween(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const {
  const CellIndex first = cellOf(from), last = cellOf(to);
  const Eigen::Vector2d along = to - from;
  const Eigen::Vector2d aside = Eigen::Vector2d(-along.y(), along.x()).normalized() * cell_size_;
  const auto isEvidence = [&](CellIndex c) { return c != first && c != last && anyObstacleIn(c, c); };
  constexpr int kSamplesPerCell = 4;  // a quarter cell apart: every cell it crosses but for a corner
  const auto samples = static_cast<int>(std::ceil(along.norm() / cell_size_ * kSamplesPerCell));
  CellIndex previous = first;
  for (int k = 1; k < samples; ++k) {
    const Eigen::Vector2d p = from + along * (static_cast<double>(k) / samples);
    const CellIndex c = cellOf(p);
    if (c == previous || c == first || c == last) continue;
    previous = c;
    // The cell, or the one a cell width to either side across the segment.
    if (!isEvidence(c) && !isEvidence(cellOf(p + aside)) && !isEvidence(cellOf(p - aside))) return false;
  }
  return true;
}

Eigen::Vector2d PenetrationGrid::centroid(CellIndex c) const {
  const Tile* tile = findTile(tileKey(c));
  const std::size_t index = slot(c);
  if (tile == nullptr || tile->counts[index] == 0) return cellCentre(c);
  return tile->sums[index] / static_cast<double>(tile->counts[index]);
}

PenetrationGrid::Tile& PenetrationGrid::tileForChange(std::uint64_t key, [[maybe_unused]] int sign) {
  // A frame's runs come in scan order: most fall in the tile of the one before.
  if (change_tile_ != nullptr && key == change_key_) return *change_tile_;
  auto it = tiles_.find(key);
  if (it == tiles_.end()) {
    assert(sign > 0 && "removing a run that was never added");
    it = tiles_.emplace(key, std::make_unique<Tile>()).first;
    it->second->sums.fill(Eigen::Vector2d::Zero());
    last_valid_ = false;  // a lookup may have cached this key as absent
  }
  change_key_ = key;
  change_tile_ = it->second.get();
  return *change_tile_;
}

void PenetrationGrid::appendToRuns(std::vector<CellRun>& runs, const Eigen::Vector2d& p) const {
  const CellIndex c = cellOf(p);
  if (!runs.empty() && runs.back().cell == c) {
    ++runs.back().count;
    runs.back().sum += p;
  } else {
    runs.push_back({c, 1, p});
  }
}

void PenetrationGrid::change(const CellRun& run, int sign) {
  const std::uint64_t key = tileKey(run.cell);
  Tile& tile = tileForChange(key, sign);
  const std::size_t index = slot(run.cell);
  const std::int64_t delta = sign * static_cast<std::int64_t>(run.count);
  std::uint32_t& cell = tile.counts[index];
  cell = static_cast<std::uint32_t>(static_cast<std::int64_t>(cell) + delta);
  // An emptied cell starts from an exact zero, so rounding never accumulates.
  tile.sums[index] = cell == 0 ? Eigen::Vector2d::Zero() : Eigen::Vector2d(tile.sums[index] + sign * run.sum);
  const std::uint64_t bit = std::uint64_t{1} << (index % 64);
  if (static_cast<std::int64_t>(cell) > obstacle_threshold_) tile.obstacles[index / 64] |= bit;
  else tile.obstacles[index / 64] &= ~bit;
  tile.total = static_cast<std::uint32_t>(static_cast<std::int64_t>(tile.total) + delta);
  if (tile.total == 0) {
    if (last_tile_ == &tile) last_valid_ = false;
    change_tile_ = nullptr;
    tiles_.erase(key);
  }
}

void PenetrationGrid::forEachCellAbove(int threshold,
                                       const std::function<void(CellIndex, int)>& fn) const {
  for (const auto& [key, tile] : tiles_) {
    const auto tx = static_cast<std::int32_t>(key >> 32);
    const auto ty = static_cast<std::int32_t>(key & 0xffffffffu);
    for (int sy = 0; sy < kTileSide; ++sy) {
      for (int sx = 0; sx < kTileSide; ++sx) {
        const auto n = static_cast<int>(tile->counts[static_cast<std::size_t>(sy * kTileSide + sx)]);
        if (n > threshold) fn({tx * kTileSide + sx, ty * kTileSide + sy}, n);
      }
    }
  }
}

}  // namespace scanfilter
