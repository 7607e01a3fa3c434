#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/jump_filter_params.hpp"

namespace scanfilter {

// Beyond the paper, after the cluster rule of step 1: a jump point only a few
// centimetres off a surface lies within the neighbour radius of eq. 5 and
// joins that surface's cluster. Such a return lies off the line through its
// two left neighbours *and* off the line through its two right neighbours.
// A true surface point lies on at least one of them: inside a wall on both,
// at a corner or a cluster's end on its own side's. Asking for both sides
// keeps one displaced point from condemning its neighbours, and a corner
// from condemning itself. A side only counts when its third neighbour lies
// on the same line: in clutter (chairs, shelves at 1° resolution) two
// neighbours do not make a surface, and extrapolating them condemns real
// returns. A thin leg is off both lines too: a cluster the cluster rule kept
// as foreground (keep_foreground_clusters) is spared.
class OffSurfaceCheck {
 public:
  explicit OffSurfaceCheck(const JumpFilterParams& params) : params_(params) {}
  void useNoiseModel(const RangeNoiseModel& model) { setNoiseModel(params_, model); }

  // Labels kJump every kValid point off both neighbour lines (nothing when
  // off_surface_check is false), except those `spared` (1: a cluster kept
  // as foreground, which lies off the background's lines by design).
  // `points` are in the sensor frame (NaN without a return); on a full turn
  // the neighbours wrap across the seam.
  void apply(std::span<const Eigen::Vector2d> points, std::span<const double> ranges, bool full_turn,
             std::span<const std::uint8_t> spared, std::span<std::uint8_t> labels);

 private:

  JumpFilterParams params_;
  std::vector<std::uint32_t> marked_;
};

}  // namespace scanfilter
