#pragma once
// One range out of light returned from several depths inside a beam's
// footprint (a "mixed pixel"): the physics of a jump point at a depth step.
#include <vector>

#include "scanfilter/sim/lidar_model.hpp"

namespace scanfilter::sim {

// Light from one part of the footprint: its depth and how much of the
// returned light it carries (the fraction of the spot there, times how well
// that surface returns light to the sensor).
struct PartialReturn {
  double range = 0.0;
  double weight = 0.0;
  bool on_thin_leg = false;  // ground truth only: this part lies on a thin leg
};

// The range the receiver reports: the weighted mean of the ranges (kLinear)
// or the inverse of the weighted mean of 1/range (kInverseDepth). NaN when
// no part returns light.
double mixRanges(RangeMixing mixing, const std::vector<PartialReturn>& parts);

}  // namespace scanfilter::sim
