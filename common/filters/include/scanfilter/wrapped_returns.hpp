#pragma once
#include <cstdint>
#include <span>

#include <Eigen/Core>

namespace scanfilter {

// The returns of one scan by beam index, wrapping across the seam of a full
// turn: what step 1's neighbour tests (off-surface check, straight runs) walk.
class WrappedReturns {
 public:
  WrappedReturns() = default;
  WrappedReturns(std::span<const Eigen::Vector2d> points, std::span<const double> ranges, bool full_turn)
      : points_(points), ranges_(ranges), full_turn_(full_turn) {}

  // Beam k's point, wrapped on a full turn (offsets of a few beams, never a
  // whole turn); null without a return or beyond the ends of a partial scan.
  const Eigen::Vector2d* at(std::int64_t k) const {
    const auto n = size();
    if (full_turn_) k += k < 0 ? n : (k >= n ? -n : 0);
    if (k < 0 || k >= n) return nullptr;
    const auto i = static_cast<std::size_t>(k);
    return ranges_[i] == ranges_[i] ? &points_[i] : nullptr;  // NaN: no return
  }
  std::int64_t size() const { return static_cast<std::int64_t>(points_.size()); }

 private:
  std::span<const Eigen::Vector2d> points_;
  std::span<const double> ranges_;
  bool full_turn_ = false;
};

}  // namespace scanfilter
