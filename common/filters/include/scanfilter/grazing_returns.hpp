#pragma once
#include <vector>

#include <Eigen/Core>

#include "scanfilter/beam_mask.hpp"

namespace scanfilter {

// Returns whose beam meets their surface at less than `max_angle_deg`
// (between the beam and the surface, 90° = head on). At grazing incidence a
// beam's footprint stretches along the surface, and the return lands where
// the footprint's mean range puts it, off the surface by centimetres, the
// same way from every viewpoint that sees the surface that way: cached,
// such returns fringe a surface seen along its length (a sofa's side from a
// robot driving past it), and a later beam running just beside it seems to
// cross it. Step 2 can keep them out of the vote (grazing_vote_max_deg).
//
// `points` are a scan's returns (NaN where none) in any frame, `sensor` the
// sensor's position in that frame, `angle_step` the scan's beam spacing
// (rad). A return's surface is the chord between the returns
// kSurfaceSpanDeg of beams either side (at least one beam), when it lies
// within `tolerance` of that chord; a return with no such surface (an end,
// a corner, a missing neighbour) is not marked.
BeamMask returnsAtGrazingIncidence(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& sensor,
                                   double angle_step, double max_angle_deg, double tolerance);

// Why a span of beams rather than the next ones: at 0.1° steps neighbouring
// returns lie millimetres apart and their range noise would decide the
// direction; over a degree the chord is centimetres long at any range.
inline constexpr double kSurfaceSpanDeg = 1.0;

}  // namespace scanfilter
