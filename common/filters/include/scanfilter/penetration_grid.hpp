#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <limits>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/cell_key.hpp"
#include "scanfilter/floor_to_int.hpp"

namespace scanfilter {

// Integer cell coordinates of a grid anchored at the world origin.
struct CellIndex {
  std::int32_t x = 0;
  std::int32_t y = 0;
  bool operator==(const CellIndex&) const = default;
};

// Consecutive points of one cell, as a frame adds them to a grid: at 0.1° a
// wall within ~3 m of the sensor puts ten or more neighbouring returns in one
// 5 cm cell, and the grid then changes that cell once per run instead of once
// per point when the frame arrives and when it expires (docs/performance.md).
struct CellRun {
  CellIndex cell;
  std::uint32_t count = 0;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();  // of the run's points, in order
};

// Point counts per cell of width W_g, stored in tiles that exist only where
// cached points are, so memory follows the cache, not the explored area, and a
// lookup costs the same however large the area is.
class PenetrationGrid {
 public:
  static constexpr int kTileBits = 5;  // 32 x 32 cells a tile
  static constexpr int kTileSide = 1 << kTileBits;

  // Cells counting more than `obstacle_threshold` are obstacles; the grid keeps
  // a bitmap of them per tile so obstacle lookups skip empty cells.
  explicit PenetrationGrid(double cell_size, int obstacle_threshold = std::numeric_limits<int>::max())
      : cell_size_(cell_size), obstacle_threshold_(obstacle_threshold) {}

  double cellSize() const { return cell_size_; }
  CellIndex cellOf(const Eigen::Vector2d& p) const {
    return {floorToInt(p.x() / cell_size_), floorToInt(p.y() / cell_size_)};
  }
  Eigen::Vector2d cellCentre(CellIndex c) const {
    return {(c.x + 0.5) * cell_size_, (c.y + 0.5) * cell_size_};
  }

  void add(const Eigen::Vector2d& p) { change({cellOf(p), 1, p}, +1); }
  void remove(const Eigen::Vector2d& p) { change({cellOf(p), 1, p}, -1); }
  // A run counts as its points would; its sum goes into the cell's at once
  // (one rounding there per run, not per point).
  void add(std::span<const CellRun> runs) {
    for (const CellRun& run : runs) change(run, +1);
  }
  void remove(std::span<const CellRun> runs) {
    for (const CellRun& run : runs) change(run, -1);
  }
  // Appends p to `runs`, extending the last run when p falls in its cell.
  void appendToRuns(std::vector<CellRun>& runs, const Eigen::Vector2d& p) const;
  void clear() {
    tiles_.clear();
    last_valid_ = false;
    change_tile_ = nullptr;
  }

  // Count of one cell; 0 where no tile exists.
  int count(CellIndex c) const;

  // Mean of the points counted in a cell (its centre when empty): where in
  // the cell the obstacle really is.
  Eigen::Vector2d centroid(CellIndex c) const;

  // Calls fn(cell, count) for every cell whose count is above `threshold`.
  void forEachCellAbove(int threshold, const std::function<void(CellIndex, int)>& fn) const;

  // Calls fn(cell) for every obstacle cell in lo..hi (inclusive); visits only
  // the tiles that exist there and, in them, only the obstacle bits.
  template <typename Fn>
  void forEachObstacleIn(CellIndex lo, CellIndex hi, Fn&& fn) const {
    forEachTileIn(lo, hi, [&](const Tile& tile, CellIndex origin) {
      for (std::size_t word = 0; word < tile.obstacles.size(); ++word) {
        for (std::uint64_t bits = tile.obstacles[word]; bits != 0; bits &= bits - 1) {
          const auto index = static_cast<int>(word * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
          const CellIndex c{origin.x + index % kTileSide, origin.y + index / kTileSide};
          if (c.x >= lo.x && c.x <= hi.x && c.y >= lo.y && c.y <= hi.y) fn(c);
        }
      }
      return false;
    });
  }

  // Whether pred(cell) holds for a cell in lo..hi (inclusive) holding at
  // least `min_count` points (at least one), obstacle or not: a leg thinner
  // than the footprint leaves fewer returns on itself than an obstacle
  // needs. Stops at the first such cell.
  template <typename Pred>
  bool anyCellHoldingIn(CellIndex lo, CellIndex hi, int min_count, Pred&& pred) const {
    const auto least = static_cast<std::uint32_t>(std::max(1, min_count));
    return anyCellIn(lo, hi, [&](const Tile& tile, CellIndex c) { return tile.counts[slot(c)] >= least && pred(c); });
  }

  // Whether any cell in lo..hi (inclusive) is an obstacle.
  bool anyObstacleIn(CellIndex lo, CellIndex hi) const {
    return anySlotIn(lo, hi, [](const Tile& tile, std::size_t slot) { return isObstacle(tile, slot); });
  }
  // Whether pred(cell) holds for an obstacle cell in lo..hi (inclusive);
  // stops at the first.
  template <typename Pred>
  bool anyObstacleIn(CellIndex lo, CellIndex hi, Pred&& pred) const {
    return anyCellIn(lo, hi, [&](const Tile& tile, CellIndex c) { return isObstacle(tile, slot(c)) && pred(c); });
  }

  // Whether the cache holds a surface all the way between two points: every
  // cell the segment from..to crosses, but the two that hold its ends, is an
  // obstacle, or the cell a cell width to either side across the segment is
  // (noise and pose error move a surface by a cell). The ends' cells are no
  // evidence of what lies between them, neither as crossed cells nor as
  // cells aside. True when no cell lies between the ends' cells: a gap
  // narrower than the cache can resolve (a pane's hole of a beam or two; a
  // crack, too).
  bool holdsSurfaceBetween(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const;

  // fn(c, count(c), centroid(c)) for every cell c of [lo, hi] (corners
  // included) holding points: one tile lookup per tile instead of one per
  // cell, the same values.
  template <typename Fn>
  void forEachCountedCellIn(CellIndex lo, CellIndex hi, Fn&& fn) const {
    anyCellIn(lo, hi, [&](const Tile& tile, CellIndex c) {
      const std::uint32_t count = tile.counts[slot(c)];
      if (count != 0) fn(c, static_cast<int>(count), Eigen::Vector2d(tile.sums[slot(c)] / static_cast<double>(count)));
      return false;
    });
  }
  // The same without the cell.
  template <typename Fn>
  void forEachCountedIn(CellIndex lo, CellIndex hi, Fn&& fn) const {
    forEachCountedCellIn(lo, hi, [&](CellIndex, int count, const Eigen::Vector2d& centroid) { fn(count, centroid); });
  }

  std::size_t tileCount() const { return tiles_.size(); }
  std::size_t memoryBytes() const { return tiles_.size() * (sizeof(Tile) + 3 * sizeof(void*)); }

 private:
  struct Tile {
    std::array<std::uint32_t, kTileSide * kTileSide> counts{};
    std::array<std::uint64_t, kTileSide * kTileSide / 64> obstacles{};  // bit per cell: count > threshold
    std::array<Eigen::Vector2d, kTileSide * kTileSide> sums;  // of the points counted, per cell
    std::uint32_t total = 0;  // sum of counts: the tile is freed at zero
  };

  static std::uint64_t tileKey(CellIndex c) { return cellKey(c.x >> kTileBits, c.y >> kTileBits); }
  static std::size_t slot(CellIndex c) {
    return static_cast<std::size_t>((c.y & (kTileSide - 1)) * kTileSide + (c.x & (kTileSide - 1)));
  }
  const Tile* findTile(std::uint64_t key) const;
  static bool isObstacle(const Tile& tile, std::size_t slot) {
    return ((tile.obstacles[slot / 64] >> (slot % 64)) & 1U) != 0;
  }
  // stop(tile, its first cell) for every tile that exists within lo..hi,
  // until it returns true; whether it did.
  template <typename Stop>
  bool forEachTileIn(CellIndex lo, CellIndex hi, Stop&& stop) const {
    for (std::int32_t ty = lo.y >> kTileBits; ty <= hi.y >> kTileBits; ++ty) {
      for (std::int32_t tx = lo.x >> kTileBits; tx <= hi.x >> kTileBits; ++tx) {
        const CellIndex origin{tx * kTileSide, ty * kTileSide};
        const Tile* tile = findTile(tileKey(origin));
        if (tile != nullptr && stop(*tile, origin)) return true;
      }
    }
    return false;
  }
  // stop(tile, cell) for every cell of lo..hi in a tile that exists, until
  // it returns true; whether it did.
  template <typename Stop>
  bool anyCellIn(CellIndex lo, CellIndex hi, Stop&& stop) const {
    return forEachTileIn(lo, hi, [&](const Tile& tile, CellIndex origin) {
      const std::int32_t y1 = std::min(hi.y, origin.y + kTileSide - 1);
      const std::int32_t x1 = std::min(hi.x, origin.x + kTileSide - 1);
      for (std::int32_t y = std::max(lo.y, origin.y); y <= y1; ++y)
        for (std::int32_t x = std::max(lo.x, origin.x); x <= x1; ++x)
          if (stop(tile, CellIndex{x, y})) return true;
      return false;
    });
  }
  // The same with the cell's slot in its tile.
  template <typename Stop>
  bool anySlotIn(CellIndex lo, CellIndex hi, Stop&& stop) const {
    return anyCellIn(lo, hi, [&](const Tile& tile, CellIndex c) { return stop(tile, slot(c)); });
  }
  // sign +1 adds the run, -1 removes it.
  void change(const CellRun& run, int sign);
  // The tile holding `key`, created when a run is added to a new one.
  Tile& tileForChange(std::uint64_t key, int sign);

  double cell_size_;
  int obstacle_threshold_;
  std::unordered_map<std::uint64_t, std::unique_ptr<Tile>> tiles_;
  // One-entry cache: consecutive lookups of a beam walk mostly hit one tile.
  // Valid only while last_valid_: every key is a possible tile (~0 is the
  // tile at cells -32..-1 in x and y), so no key can mean "none".
  mutable bool last_valid_ = false;
  mutable std::uint64_t last_key_ = 0;
  mutable const Tile* last_tile_ = nullptr;
  // The same for changes (add, remove), which may create or free the tile;
  // valid while change_tile_ is set (every key is a possible tile, ~0 too).
  std::uint64_t change_key_ = 0;
  Tile* change_tile_ = nullptr;
};

}  // namespace scanfilter
