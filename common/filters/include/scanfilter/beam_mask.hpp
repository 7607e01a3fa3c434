#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace scanfilter {

// One yes/no per beam of a scan (which returns are usable, kept, at an edge).
// A byte each: step 2 reads such flags several times a beam, and
// std::vector<bool>'s bit arithmetic for each read and write was 7 % of its
// instructions at 3,600 beams (docs/performance.md). A type of its own, not a
// std::vector<std::uint8_t>, so that a scan's labels (where 0 means kept)
// cannot be passed for a mask by mistake.
class BeamMask {
 public:
  BeamMask() = default;
  explicit BeamMask(std::size_t beams, bool value = false) : flags_(beams, value ? 1 : 0) {}

  bool operator[](std::size_t beam) const { return flags_[beam] != 0; }
  void set(std::size_t beam, bool value) { flags_[beam] = value ? 1 : 0; }
  void push_back(bool value) { flags_.push_back(value ? 1 : 0); }
  void assign(std::size_t beams, bool value) { flags_.assign(beams, value ? 1 : 0); }
  // Empty, keeping the storage for the next scan's mask.
  void clear() { flags_.clear(); }
  std::size_t size() const { return flags_.size(); }
  bool empty() const { return flags_.empty(); }
  bool operator==(const BeamMask&) const = default;

 private:
  std::vector<std::uint8_t> flags_;
};

}  // namespace scanfilter
