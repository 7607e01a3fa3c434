#include "scanfilter/thin_object_check.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/scan_geometry.hpp"

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
  const double across = std::abs(cross(unit, w));
  return across <= halfWidthAt(along, angle_step);
}

BeamMask inFrontOfBothSides(const Scan& scan, std::size_t max_beams, double depth_step) {
  const std::size_t n = scan.size();
  BeamMask out(n);
  if (n < 3) return out;  // no stretch has two sides
  // A full turn goes on across its seam, as step 1's clusters do; a partial
  // one has no beam beyond its ends.
  const bool wraps = isFullTurn(scan);
  const std::size_t longest = std::min(max_beams, n - 2);
  // Every stretch [a, a + length) of returns: flagged when both beams beside
  // it return farther than its farthest return by more than the step.
  for (std::size_t a = wraps ? 0 : 1; a < n; ++a) {
    const std::size_t before = (a + n - 1) % n;
    if (!scan.hasReturn(before)) continue;
    double farthest = 0.0;
    for (std::size_t length = 1; length <= longest && (wraps || a + length < n); ++length) {
      const std::size_t last = (a + length - 1) % n;
      if (!scan.hasReturn(last)) break;
      farthest = std::max(farthest, scan.ranges[last]);
      const double beyond = farthest + depth_step;
      if (scan.ranges[before] <= beyond) break;  // `beyond` only grows: no longer stretch passes either
      const std::size_t after = (a + length) % n;
      if (!scan.hasReturn(after) || scan.ranges[after] <= beyond) continue;
      for (std::size_t k = 0; k < length; ++k) out.set((a + k) % n, true);
    }
  }
  return out;
}

}  // namespace scanfilter
