#include "scanfilter/free_space_check.hpp"

#include <algorithm>
#include <cmath>

namespace scanfilter {

FreeSpaceCheck::Sighting FreeSpaceCheck::sighting(const RangeImage& frame, const Eigen::Vector2d& p) const {
  const auto b = frame.bracket(p);
  if (!b || !std::isfinite(b->first) || !std::isfinite(b->second)) return Sighting::kNone;
  // Farther returns move more (range noise, a pose's leftover rotation).
  const double margin = margin_ + margin_per_m_ * b->distance;
  const double beyond = b->distance + margin;
  const double nearer = std::min(b->first, b->second);
  if (nearer > beyond) {
    // The outer beams too: with a beam of pose error between the frames, an
    // edge point's bracket can fall on the background just beside the edge.
    if (!std::isfinite(b->before) || !std::isfinite(b->after)) return Sighting::kNone;
    const double outer = std::min(b->before, b->after);
    if (outer <= beyond) return Sighting::kNone;
    // A dip below the outer beams is something standing partly in the bracketing ones.
    if (nearer < outer - dip_) return Sighting::kNone;
    return Sighting::kThrough;
  }
  const bool hit = std::abs(b->first - b->distance) <= margin ||
                   std::abs(b->second - b->distance) <= margin;
  return hit ? Sighting::kHit : Sighting::kNone;
}

}  // namespace scanfilter
