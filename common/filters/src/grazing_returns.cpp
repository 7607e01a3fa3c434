#include "scanfilter/grazing_returns.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

BeamMask returnsAtGrazingIncidence(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& sensor,
                                   double angle_step, double max_angle_deg, double tolerance) {
  BeamMask grazing(points.size());
  const double step_deg = std::abs(angle_step) * 180.0 / std::numbers::pi;
  if (!(max_angle_deg > 0.0) || !(step_deg > 0.0)) return grazing;
  // Beams either side that span kSurfaceSpanDeg, at least one, at most the scan.
  const auto span = static_cast<std::size_t>(
      std::clamp(std::ceil(kSurfaceSpanDeg / step_deg - 1e-9), 1.0, static_cast<double>(points.size())));
  const double sin_max = std::sin(max_angle_deg * std::numbers::pi / 180.0);
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
