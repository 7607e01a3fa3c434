#pragma once
#include <optional>
#include <span>

#include <Eigen/Core>

namespace scanfilter {

// Neighbouring beams of a fine scanner (0.1-0.25° apart) cross nearly the
// same cells, so the fast step 2 walks a run of them once: the beams of a
// bundle leave one origin, and one band around an axis segment holds every
// band their own walks would cover. The obstacle cells found in it are then
// tested against each beam with the exact rule, so a bundle changes what is
// visited, never a label.

// One beam of a bundle: the direction of its point from the origin (a unit
// vector) and how far along it its walk reaches.
struct BundledBeam {
  Eigen::Vector2d unit;
  double reach = 0.0;
};

// The segment origin -> origin + axis * length and the half width of the band
// around it.
struct BundleBand {
  Eigen::Vector2d axis;
  double length = 0.0;
  double half_width = 0.0;
};

// A band holding every point within `beam_half_width` of any of the segments
// origin -> origin + reach * unit; the axis bisects the first and the last
// beam. Nullopt when a beam lies more than 60° off that axis (the bound
// below needs them in front of it; the band would be pointless long before).
//
// Why it holds: a point of beam k at s <= reach_k lies s·cos(a_k) along the
// axis (within [0, length]) and s·|sin(a_k)| <= spread off it, so a point
// within beam_half_width of beam k lies within beam_half_width + spread of
// the axis segment.
std::optional<BundleBand> bundleBand(std::span<const BundledBeam> beams, double beam_half_width);

// What bundleBand's spread comes to when every beam lies between `first`
// and `last` (a run of one scan) and none reaches beyond `max_reach`; in
// constant time, to decide while growing a bundle whether one more beam is
// worth it. Infinite when the two are 120° or more apart.
double fanSpread(const BundledBeam& first, const BundledBeam& last, double max_reach);

}  // namespace scanfilter
