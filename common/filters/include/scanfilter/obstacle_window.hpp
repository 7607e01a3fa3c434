#pragma once
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/cell_bitmap.hpp"
#include "scanfilter/cell_slots.hpp"
#include "scanfilter/floor_to_int.hpp"
#include "scanfilter/penetration_grid.hpp"

namespace scanfilter {

// A dense snapshot of the obstacle cells of a PenetrationGrid inside one
// rectangle of cells: the reach of the frame being judged. Built once per
// frame, its size follows the sensor's range, never the map's. Besides the
// cells it flags 8 x 8-cell blocks holding any obstacle, so a beam walk skips
// free space a block at a time, and keeps the cells as bits by row and by
// column, so that inside a block the walk reads the few cells across the
// beam at each step as one word.
class ObstacleWindow {
 public:
  static constexpr int kBlockBits = 3;
  static constexpr int kBlockSide = 1 << kBlockBits;

  // Snapshots the grid's obstacle cells in lo..hi (inclusive), each with
  // where its obstacle is, position(cell): looked up once a frame rather
  // than at every beam that passes the cell.
  template <typename Position>
  void build(const PenetrationGrid& grid, CellIndex lo, CellIndex hi, Position&& position) {
    cell_size_ = grid.cellSize();
    resize(lo, hi);
    grid.forEachObstacleIn(lo, hi, [&](CellIndex c) { mark(c, position(c)); });
  }
  // Takes cell c out of the snapshot (nothing if it is not in it). Its
  // block stays flagged: the flags only let a walk skip, so a superset is
  // safe.
  void erase(CellIndex c);

  bool isObstacle(CellIndex c) const { return indexOf(c) != CellSlots::kNone; }

  // Calls pred(cell, position) for the obstacle cells whose centre can lie
  // within `half_width` of segment a-b (a superset: pred makes the exact
  // test) and returns true at the first cell for which pred does.
  template <typename Pred>
  bool anyAlongRay(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double half_width, Pred&& pred) const;

 private:
  void resize(CellIndex lo, CellIndex hi);
  void mark(CellIndex c, const Eigen::Vector2d& position);
  // Offset of a cell inside the window's rectangle (c must lie in it).
  std::size_t offsetOf(CellIndex c) const {
    return static_cast<std::size_t>(c.y - lo_.y) * width_ + static_cast<std::size_t>(c.x - lo_.x);
  }
  std::int32_t indexOf(CellIndex c) const {
    const auto x = static_cast<std::uint32_t>(c.x - lo_.x);
    const auto y = static_cast<std::uint32_t>(c.y - lo_.y);
    if (x >= width_ || y >= height_) return CellSlots::kNone;  // also catches c < lo (wraps)
    return cells_[static_cast<std::size_t>(y) * width_ + x];
  }
  bool blockHasObstacle(std::int32_t bx, std::int32_t by) const {
    const auto x = static_cast<std::uint32_t>(bx - block_lo_.x);
    const auto y = static_cast<std::uint32_t>(by - block_lo_.y);
    if (x >= block_width_ || y >= block_height_) return false;
    return blocks_[static_cast<std::size_t>(y) * block_width_ + x] != 0;
  }

  double cell_size_ = 1.0;
  CellIndex lo_;
  std::uint32_t width_ = 0;
  std::uint32_t height_ = 0;
  CellSlots cells_;  // index into positions_, kNone for none
  std::vector<Eigen::Vector2d> positions_;
  CellIndex block_lo_;
  std::uint32_t block_width_ = 0;
  std::uint32_t block_height_ = 0;
  std::vector<std::uint8_t> blocks_;
  CellBitmap rows_;     // bit x - lo_.x of row y - lo_.y
  CellBitmap columns_;  // bit y - lo_.y of row x - lo_.x
};

namespace detail {
// Float slack on the walk's bounds: pred re-runs the exact test on every cell
// visited, so the walk only has to be a superset.
inline constexpr double kBoundSlack = 1e-9;
}  // namespace detail

template <typename Pred>
bool ObstacleWindow::anyAlongRay(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double half_width,
                                 Pred&& pred) const {
  const Eigen::Vector2d d = b - a;
  const int axis = std::abs(d.x()) >= std::abs(d.y()) ? 0 : 1;  // walk the dominant axis
  const int other = 1 - axis;
  const double inv_w = 1.0 / cell_size_;
  const double slope = d[other] / d[axis];
  // A centre within half_width of the line sits within half_width / |cos| of it along `other`.
  const double band = half_width * std::sqrt(1.0 + slope * slope) + detail::kBoundSlack;
  // Cell indices whose centres lie in [lo, hi]: centre = (i + 0.5) * w.
  const auto first = [inv_w](double lo) { return -floorToInt(-(lo * inv_w - 0.5)); };
  const auto last = [inv_w](double hi) { return floorToInt(hi * inv_w - 0.5); };
  const auto lineAt = [&](std::int32_t i) { return a[other] + ((i + 0.5) * cell_size_ - a[axis]) * slope; };
  const auto cell = [axis](std::int32_t i, std::int32_t j) { return axis == 0 ? CellIndex{i, j} : CellIndex{j, i}; };

  // The window's cells along the walk (i) and across it (j).
  const std::int32_t i_min = axis == 0 ? lo_.x : lo_.y;
  const std::int32_t j_min = axis == 0 ? lo_.y : lo_.x;
  const auto i_max = static_cast<std::int32_t>(i_min + static_cast<std::int32_t>(axis == 0 ? width_ : height_) - 1);
  const auto j_max = static_cast<std::int32_t>(j_min + static_cast<std::int32_t>(axis == 0 ? height_ : width_) - 1);
  const std::int32_t lo = first(std::min(a[axis], b[axis]) - half_width - detail::kBoundSlack);
  const std::int32_t hi = last(std::max(a[axis], b[axis]) + half_width + detail::kBoundSlack);
  for (std::int32_t chunk = lo >> kBlockBits; chunk <= hi >> kBlockBits; ++chunk) {
    const std::int32_t i0 = std::max(lo, chunk * kBlockSide);
    const std::int32_t i1 = std::min(hi, chunk * kBlockSide + kBlockSide - 1);
    // Blocks the band crosses within this chunk of columns; all free: skip it.
    const double y0 = lineAt(i0), y1 = lineAt(i1);
    const std::int32_t b0 = first(std::min(y0, y1) - band) >> kBlockBits;
    const std::int32_t b1 = last(std::max(y0, y1) + band) >> kBlockBits;
    bool occupied = false;
    for (std::int32_t bj = b0; bj <= b1 && !occupied; ++bj)
      occupied = axis == 0 ? blockHasObstacle(chunk, bj) : blockHasObstacle(bj, chunk);
    if (!occupied) continue;
    for (std::int32_t i = i0; i <= i1; ++i) {
      if (i < i_min || i > i_max) continue;  // this column is outside the window
      const double line = lineAt(i);
      const std::int32_t j_lo = std::max(first(line - band), j_min), j_hi = std::min(last(line + band), j_max);
      for (std::int32_t j0 = j_lo; j0 <= j_hi; j0 += CellBitmap::kMaxRun) {
        const int count = std::min(CellBitmap::kMaxRun, j_hi - j0 + 1);
        std::uint64_t bits = axis == 0 ? columns_.run(i - i_min, j0 - j_min, count) : rows_.run(i - i_min, j0 - j_min, count);
        for (; bits != 0; bits &= bits - 1) {  // the obstacle cells of this step, in j order
          const CellIndex c = cell(i, j0 + std::countr_zero(bits));
          if (pred(c, positions_[static_cast<std::size_t>(indexOf(c))])) return true;
        }
      }
    }
  }
  return false;
}

}  // namespace scanfilter
