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
  for (std::size_t i = span; i + span < points.size(); ++i) {
    const Eigen::Vector2d& a = points[i - span];
    const Eigen::Vector2d& b = points[i + span];
    const Eigen::Vector2d& p = points[i];
    if (!a.allFinite() || !b.allFinite() || !p.allFinite() || a == b) continue;
    if (isFartherFromLineThan(p, a, b, tolerance)) continue;  // no one surface through it
    const Eigen::Vector2d along = (b - a).normalized();
    const Eigen::Vector2d beam = p - sensor;
    const double length = beam.norm();
    if (!(length > 0.0)) continue;
    // sin of the angle between beam and surface: |beam x along| / |beam|.
    grazing.set(i, std::abs(cross(beam, along)) < sin_max * length);
  }
  return grazing;
}

}  // namespace scanfilter
