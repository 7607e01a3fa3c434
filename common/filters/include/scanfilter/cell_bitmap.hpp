#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace scanfilter {

// One bit per cell of a rectangle, a row of 64-bit words per row: a short run
// of neighbouring cells of one row is read as one word, so a search looks
// only at the cells whose bit is set (most of a snapshot is free space).
class CellBitmap {
 public:
  static constexpr int kBitsPerWord = 64;
  static constexpr int kMaxRun = kBitsPerWord - 1;

  // `rows` rows of `width` bits each, all clear.
  void reset(int width, int rows) {
    words_per_row_ = (width + kBitsPerWord - 1) / kBitsPerWord + 1;  // +1: a run may read one word past the row
    words_.assign(static_cast<std::size_t>(words_per_row_) * static_cast<std::size_t>(rows), 0);
  }

  void set(int x, int row) { wordOf(x, row) |= bitOf(x); }
  void clear(int x, int row) { wordOf(x, row) &= ~bitOf(x); }

  // Bits x0 .. x0 + count - 1 of `row`, lowest first (0 <= x0, 1 <= count
  // <= kMaxRun, x0 + count <= width).
  std::uint64_t run(int row, int x0, int count) const {
    const std::uint64_t* words = words_.data() + static_cast<std::size_t>(row) * static_cast<std::size_t>(words_per_row_);
    const int word = x0 / kBitsPerWord, shift = x0 % kBitsPerWord;
    std::uint64_t bits = words[word] >> shift;
    if (shift != 0) bits |= words[word + 1] << (kBitsPerWord - shift);
    return bits & ((std::uint64_t{1} << count) - 1);
  }

 private:
  std::uint64_t& wordOf(int x, int row) {
    return words_[static_cast<std::size_t>(row) * static_cast<std::size_t>(words_per_row_) +
                  static_cast<std::size_t>(x / kBitsPerWord)];
  }
  static std::uint64_t bitOf(int x) { return std::uint64_t{1} << (x % kBitsPerWord); }

  int words_per_row_ = 0;
  std::vector<std::uint64_t> words_;
};

}  // namespace scanfilter
