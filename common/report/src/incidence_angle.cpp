#include "scanfilter/incidence_angle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

std::vector<double> incidenceAnglesDeg(const Scan& scan, const SensorInfo& sensor, double surface_tolerance) {
  constexpr double kRadToDeg = 180.0 / std::numbers::pi;
  BeamDirectionTable directions;
  std::vector<Eigen::Vector2d> points;
  // The sensor's frame: the beam is the point itself, and angles do not
  // depend on the frame.
  sensorFramePoints(scan, sensor, directions, points);
  std::vector<double> out(scan.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto surface = localSurfaceDirection(points, i, surface_tolerance);
    const Eigen::Vector2d& beam = points[i];
    if (!surface || beam.squaredNorm() == 0.0) continue;
    // cos(incidence) = |beam · normal| = |beam × surface| / (|beam| |surface|).
    const double cross = std::abs(beam.x() * surface->y() - beam.y() * surface->x());
    out[i] = kRadToDeg * std::acos(std::min(1.0, cross / (beam.norm() * surface->norm())));
  }
  return out;
}

}  // namespace scanfilter
