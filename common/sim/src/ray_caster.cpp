#include "scanfilter/sim/ray_caster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter::sim {

namespace {
// Endpoints closer than this are one corner; directions closer than this
// angle (in |cos|) are one straight wall, not a junction.
constexpr double kSamePointTolerance = 1e-6;
constexpr double kStraightCos = 0.94;  // about 20°
constexpr double kParallelTolerance = 1e-12;
}  // namespace

RayCaster::RayCaster(const Scene& scene) : scene_(scene) {
  const auto& s = scene.segments;
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      for (const auto& p : {s[i].a, s[i].b}) {
        if ((p - s[j].a).norm() > kSamePointTolerance && (p - s[j].b).norm() > kSamePointTolerance) continue;
        const Eigen::Vector2d di = (s[i].b - s[i].a).normalized();
        const Eigen::Vector2d dj = (s[j].b - s[j].a).normalized();
        if (std::abs(di.dot(dj)) < kStraightCos) corners_.push_back(p);
      }
    }
  }
}

std::optional<RayHit> RayCaster::cast(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                                      double max_range) const {
  RayHit best;
  best.range = max_range;
  bool found = false;
  for (const Segment& seg : scene_.segments) {
    const Eigen::Vector2d e = seg.b - seg.a;
    const double denom = cross(direction, e);
    if (std::abs(denom) < kParallelTolerance) continue;
    const Eigen::Vector2d w = seg.a - origin;
    const double t = cross(w, e) / denom;          // along the ray
    const double u = cross(w, direction) / denom;  // along the segment
    if (t <= 0.0 || t >= best.range || u < 0.0 || u > 1.0) continue;
    best.range = t;
    best.point = origin + t * direction;
    Eigen::Vector2d n(-e.y(), e.x());
    n.normalize();
    best.normal = n.dot(direction) > 0.0 ? Eigen::Vector2d(-n) : n;
    best.material = seg.material;
    best.is_leg = false;
    found = true;
  }
  for (const Leg& leg : scene_.legs) {
    const Eigen::Vector2d oc = origin - leg.centre;
    const double b = oc.dot(direction);
    const double c = oc.squaredNorm() - leg.radius * leg.radius;
    const double disc = b * b - c;
    if (disc < 0.0) continue;
    const double t = -b - std::sqrt(disc);
    if (t <= 0.0 || t >= best.range) continue;
    best.range = t;
    best.point = origin + t * direction;
    best.normal = (best.point - leg.centre).normalized();
    best.material = Material::kRough;
    best.is_leg = true;
    found = true;
  }
  if (!found) return std::nullopt;
  return best;
}

double RayCaster::distanceToSurface(const Eigen::Vector2d& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& seg : scene_.segments) {
    const Eigen::Vector2d e = seg.b - seg.a;
    const double t = std::clamp((p - seg.a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (p - (seg.a + t * e)).norm());
  }
  for (const Leg& leg : scene_.legs) best = std::min(best, std::abs((p - leg.centre).norm() - leg.radius));
  return best;
}

double RayCaster::distanceToCorner(const Eigen::Vector2d& p) const {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& c : corners_) best = std::min(best, (p - c).norm());
  return best;
}

}  // namespace scanfilter::sim
