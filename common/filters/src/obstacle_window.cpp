#include "scanfilter/obstacle_window.hpp"

#include <algorithm>

namespace scanfilter {

void ObstacleWindow::resize(CellIndex lo, CellIndex hi) {
  lo_ = lo;
  width_ = static_cast<std::uint32_t>(std::max(0, hi.x - lo.x + 1));
  height_ = static_cast<std::uint32_t>(std::max(0, hi.y - lo.y + 1));
  cells_.reset(static_cast<std::size_t>(width_) * height_);
  positions_.clear();
  block_lo_ = {lo.x >> kBlockBits, lo.y >> kBlockBits};
  block_width_ = static_cast<std::uint32_t>((hi.x >> kBlockBits) - block_lo_.x + 1);
  block_height_ = static_cast<std::uint32_t>((hi.y >> kBlockBits) - block_lo_.y + 1);
  blocks_.assign(static_cast<std::size_t>(block_width_) * block_height_, 0);
  rows_.reset(static_cast<int>(width_), static_cast<int>(height_));
  columns_.reset(static_cast<int>(height_), static_cast<int>(width_));
}

void ObstacleWindow::mark(CellIndex c, const Eigen::Vector2d& position) {
  cells_.set(offsetOf(c), static_cast<std::int32_t>(positions_.size()));
  positions_.push_back(position);
  rows_.set(c.x - lo_.x, c.y - lo_.y);
  columns_.set(c.y - lo_.y, c.x - lo_.x);
  blocks_[static_cast<std::size_t>((c.y >> kBlockBits) - block_lo_.y) * block_width_ +
          static_cast<std::size_t>((c.x >> kBlockBits) - block_lo_.x)] = 1;
}

void ObstacleWindow::erase(CellIndex c) {
  if (!isObstacle(c)) return;
  cells_.set(offsetOf(c), CellSlots::kNone);
  rows_.clear(c.x - lo_.x, c.y - lo_.y);
  columns_.clear(c.y - lo_.y, c.x - lo_.x);
}

}  // namespace scanfilter
