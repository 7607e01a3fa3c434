#pragma once
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
// rectangle grows with the square of the sensor's range (40,000 cells for
// the 8 x 10 m hall, 1.4 million for a 30 m scanner's 60 x 60 m), and
// rewriting all of it every frame pushed the grid out of the cache.
class CellSlots {
 public:
  static constexpr std::int32_t kNone = -1;

  // Ready for a rectangle of `cells` cells, every one kNone.
  void reset(std::size_t cells) {
    for (const std::size_t offset : set_) slots_[offset] = kNone;
    set_.clear();
    if (slots_.size() < cells) slots_.resize(cells, kNone);
  }
  void set(std::size_t offset, std::int32_t slot) {
    slots_[offset] = slot;
    set_.push_back(offset);
  }
  std::int32_t operator[](std::size_t offset) const { return slots_[offset]; }

 private:
  std::vector<std::int32_t> slots_;  // at least the current rectangle; kNone but at set_
  std::vector<std::size_t> set_;     // offsets set since the last reset
};

}  // namespace scanfilter
