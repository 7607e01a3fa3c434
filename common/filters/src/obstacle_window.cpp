#include "scanfilter/obstacle_window.hpp"

#include <algorithm>

namespace scanfilter {

void ObstacleWindow::build(const PenetrationGrid& grid, CellIndex lo, CellIndex hi) {
  cell_size_ = grid.cellSize();
  lo_ = lo;
  width_ = static_cast<std::uint32_t>(std::max(0, hi.x - lo.x + 1));
  height_ = static_cast<std::uint32_t>(std::max(0, hi.y - lo.y + 1));
  cells_.assign(static_cast<std::size_t>(width_) * height_, 0);
  block_lo_ = {lo.x >> kBlockBits, lo.y >> kBlockBits};
  block_width_ = static_cast<std::uint32_t>((hi.x >> kBlockBits) - block_lo_.x + 1);
  block_height_ = static_cast<std::uint32_t>((hi.y >> kBlockBits) - block_lo_.y + 1);
  blocks_.assign(static_cast<std::size_t>(block_width_) * block_height_, 0);
  grid.forEachObstacleIn(lo, hi, [this](CellIndex c) {
    cells_[static_cast<std::size_t>(c.y - lo_.y) * width_ + static_cast<std::size_t>(c.x - lo_.x)] = 1;
    blocks_[static_cast<std::size_t>((c.y >> kBlockBits) - block_lo_.y) * block_width_ +
            static_cast<std::size_t>((c.x >> kBlockBits) - block_lo_.x)] = 1;
  });
}

}  // namespace scanfilter
