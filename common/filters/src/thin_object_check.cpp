#include "scanfilter/thin_object_check.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

std::optional<ThinObjectCheck::AlongBeam> ThinObjectCheck::alongInFootprint(const Eigen::Vector2d& origin,
                                                                             const Eigen::Vector2d& p,
                                                                             const Eigen::Vector2d& q,
                                                                             double angle_step) const {
  const Eigen::Vector2d beam = p - origin;
  const double length = beam.norm();
  if (!(length > 0.0)) return std::nullopt;  // no beam
  const Eigen::Vector2d unit = beam / length;
  const Eigen::Vector2d w = q - origin;
  const double along = w.dot(unit);
  if (along <= 0.0) return std::nullopt;  // behind the sensor
  if (std::abs(cross(unit, w)) > halfWidthAt(along, angle_step)) return std::nullopt;
  return AlongBeam{along, length};
}

bool ThinObjectCheck::inFootprintInFront(const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                                         const Eigen::Vector2d& q, double angle_step) const {
  const auto at = alongInFootprint(origin, p, q, angle_step);
  return at && at->along <= at->length - depth_step_;
}

bool ThinObjectCheck::inFootprintBehind(const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                                        const Eigen::Vector2d& q, double angle_step, double reach) const {
  const auto at = alongInFootprint(origin, p, q, angle_step);
  return at && at->along >= at->length + depth_step_ && at->along <= reach;
}

std::vector<StandsInFront> standingInFront(const Scan& scan, std::size_t max_beams, double depth_step) {
  const std::size_t n = scan.size();
  std::vector<StandsInFront> out(n, StandsInFront::kNo);
  if (n < 3) return out;  // no stretch has two sides
  // A full turn goes on across its seam, as step 1's clusters do; a partial
  // one has no beam beyond its ends.
  const bool wraps = isFullTurn(scan);
  const std::size_t longest = std::min(max_beams, n - 2);
  // Every stretch [a, a + length) of returns: flagged when both beams beside
  // it return farther than its farthest return by more than the step, or
  // nothing.
  for (std::size_t a = wraps ? 0 : 1; a < n; ++a) {
    const std::size_t before = (a + n - 1) % n;
    const bool open_before = !scan.hasReturn(before);
    double farthest = 0.0;
    for (std::size_t length = 1; length <= longest && (wraps || a + length < n); ++length) {
      const std::size_t last = (a + length - 1) % n;
      if (!scan.hasReturn(last)) break;
      farthest = std::max(farthest, scan.ranges[last]);
      const double beyond = farthest + depth_step;
      if (!open_before && scan.ranges[before] <= beyond) break;  // `beyond` only grows: no longer stretch passes
      const std::size_t after = (a + length) % n;
      const bool open_after = !scan.hasReturn(after);
      if (!open_after && scan.ranges[after] <= beyond) continue;
      const StandsInFront how =
          open_before || open_after ? StandsInFront::kBesideNoReturn : StandsInFront::kOfBothSides;
      for (std::size_t k = 0; k < length; ++k) {
        StandsInFront& stands = out[(a + k) % n];
        if (stands != StandsInFront::kOfBothSides) stands = how;  // both sides farther is the stronger claim
      }
    }
  }
  return out;
}

}  // namespace scanfilter
