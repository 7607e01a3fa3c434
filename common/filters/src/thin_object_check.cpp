#include "scanfilter/thin_object_check.hpp"

#include <algorithm>
#include <cmath>

namespace scanfilter {

bool ThinObjectCheck::inFootprintInFront(const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                                         const Eigen::Vector2d& q, double angle_step) const {
  const Eigen::Vector2d beam = p - origin;
  const double length = beam.norm();
  if (!(length > 0.0)) return false;
  const Eigen::Vector2d unit = beam / length;
  const Eigen::Vector2d w = q - origin;
  const double along = w.dot(unit);
  if (along <= 0.0 || along > length - depth_step_) return false;  // behind the sensor, or not in front of p
  const double across = std::abs(w.x() * unit.y() - w.y() * unit.x());
  return across <= halfWidthAt(along, angle_step);
}

BeamMask inFrontOfBothSides(const Scan& scan, std::size_t max_beams, double depth_step) {
  const std::size_t n = scan.size();
  BeamMask out(n);
  // Every stretch [a, b] of returns, at most max_beams long, not at the
  // scan's ends: flagged when both beams beside it return farther than its
  // farthest return by more than the step.
  for (std::size_t a = 1; a + 1 < n; ++a) {
    if (!scan.hasReturn(a - 1)) continue;
    double farthest = 0.0;
    for (std::size_t b = a; b + 1 < n && b - a < max_beams && scan.hasReturn(b); ++b) {
      farthest = std::max(farthest, scan.ranges[b]);
      const double beyond = farthest + depth_step;
      if (scan.ranges[a - 1] <= beyond) break;  // `beyond` only grows: no longer stretch passes either
      if (!scan.hasReturn(b + 1) || scan.ranges[b + 1] <= beyond) continue;
      for (std::size_t k = a; k <= b; ++k) out.set(k, true);
    }
  }
  return out;
}

}  // namespace scanfilter
