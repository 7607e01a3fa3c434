#include "scanfilter/sim/tour_clearance.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter::sim {

namespace {

// 0 when they cross, else the distance from the nearest end to the other
// segment.
double distanceBetweenSegments(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                               const Eigen::Vector2d& d) {
  const double abc = cross(b - a, c - a), abd = cross(b - a, d - a);
  const double cda = cross(d - c, a - c), cdb = cross(d - c, b - c);
  if (abc * abd < 0.0 && cda * cdb < 0.0) return 0.0;
  return std::min({distanceToSegment(a, c, d), distanceToSegment(b, c, d), distanceToSegment(c, a, b),
                   distanceToSegment(d, a, b)});
}

std::string where(const Eigen::Vector2d& p) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << '(' << p.x() << ", " << p.y() << ')';
  return text.str();
}

}  // namespace

std::optional<TourObstruction> firstObstruction(const Scene& scene) {
  const auto& waypoints = scene.trajectory.waypoints;
  const double radius = scene.trajectory.robot_radius;
  for (std::size_t k = 0; k + 1 < waypoints.size(); ++k) {
    const Eigen::Vector2d& from = waypoints[k];
    const Eigen::Vector2d& to = waypoints[k + 1];
    for (const Segment& s : scene.segments) {
      const double gap = distanceBetweenSegments(from, to, s.a, s.b);
      if (gap < radius) return TourObstruction{k, gap, "the wall or box side " + where(s.a) + "-" + where(s.b)};
    }
    for (const Leg& leg : scene.legs) {
      const double gap = distanceToSegment(leg.centre, from, to) - leg.radius;
      if (gap < radius) return TourObstruction{k, std::max(gap, 0.0), "the leg at " + where(leg.centre)};
    }
  }
  return std::nullopt;
}

}  // namespace scanfilter::sim
