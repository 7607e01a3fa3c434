#include "scanfilter/grazing_returns.hpp"

#include <cmath>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

BeamMask returnsAtGrazingIncidence(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& sensor,
                                   double angle_step, double max_angle_deg, double tolerance) {
  BeamMask grazing(points.size());
  if (!(max_angle_deg > 0.0) || !(std::abs(angle_step) > 0.0)) return grazing;
  const std::size_t span = beamsSpanning(kSurfaceSpanDeg, angle_step, points.size());  // beams either side
  const double sin_max = std::sin(degreesToRadians(max_angle_deg));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto surface = localSurfaceDirection(points, i, tolerance, span);
    if (!surface) continue;
    const Eigen::Vector2d beam = points[i] - sensor;
    // sin of the angle between beam and surface: |beam x surface| / (|beam| |surface|).
    grazing.set(i, std::abs(cross(beam, *surface)) < sin_max * beam.norm() * surface->norm());
  }
  return grazing;
}

}  // namespace scanfilter
