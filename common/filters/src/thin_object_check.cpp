#include "scanfilter/thin_object_check.hpp"

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
  // Whether beam j returns farther than beam k by more than the step.
  const auto farther = [&](std::size_t j, std::size_t k) {
    return scan.hasReturn(j) && scan.ranges[j] > scan.ranges[k] + depth_step;
  };
  std::size_t start = 0;
  while (start < n) {
    if (!scan.hasReturn(start)) {
      ++start;
      continue;
    }
    std::size_t end = start + 1;  // one past the run's last return
    while (end < n && scan.hasReturn(end) && std::abs(scan.ranges[end] - scan.ranges[end - 1]) <= depth_step) ++end;
    const bool in_front =
        end - start <= max_beams && start > 0 && end < n && farther(start - 1, start) && farther(end, end - 1);
    for (std::size_t k = start; in_front && k < end; ++k) out.set(k, true);
    start = end;
  }
  return out;
}

}  // namespace scanfilter
