#pragma once
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace scanfilter {

// A number per cell of a rectangle of cells (row-major, offsets given by the
// caller), kNone where nothing was set: the per-frame index from a cell to
// its obstacle in the aligner's and the judging window's snapshots.
//
// reset() clears only the cells set since the last reset, not the whole
// rectangle: a frame marks a few thousand obstacle cells, while its
// rectangle grows with the square of the sensor's range (40,000 cells in the
// 8 x 10 m hall, up to 480,000 for a 20 m scanner in a 40 x 30 m warehouse,
// where refilling it every frame cost 2-7 % of the filter's time:
// docs/performance.md).
class CellSlots {
 public:
  static constexpr std::int32_t kNone = -1;

  // Ready for a rectangle of `cells` cells, every one kNone.
  void reset(std::size_t cells) {
    for (const std::size_t offset : set_offsets_) slots_[offset] = kNone;
    set_offsets_.clear();
    if (slots_.size() < cells) slots_.resize(cells, kNone);
    cells_ = cells;
  }
  void set(std::size_t offset, std::int32_t slot) {
    assert(offset < cells_ && "outside the rectangle");  // the buffer may be larger: it keeps its peak
    slots_[offset] = slot;
    set_offsets_.push_back(offset);
  }
  std::int32_t operator[](std::size_t offset) const {
    assert(offset < cells_ && "outside the rectangle");
    return slots_[offset];
  }

 private:
  std::vector<std::int32_t> slots_;        // at least the rectangle; kNone except at set_offsets_
  std::vector<std::size_t> set_offsets_;   // offsets set since the last reset
  std::size_t cells_ = 0;                  // the current rectangle's cells
};

}  // namespace scanfilter
