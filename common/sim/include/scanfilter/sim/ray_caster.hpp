#pragma once
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

struct RayHit {
  double range = 0.0;
  Eigen::Vector2d point;
  Eigen::Vector2d normal;  // unit, facing the ray
  Material material = Material::kRough;
  bool is_leg = false;
};

// Nearest intersection of a ray with a scene's walls and legs.
class RayCaster {
 public:
  explicit RayCaster(const Scene& scene);

  std::optional<RayHit> cast(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                             double max_range) const;

  // Distance from p to the nearest surface (wall or leg) of the scene.
  double distanceToSurface(const Eigen::Vector2d& p) const;

  // Distance from p to the nearest corner (where two walls meet at an angle).
  double distanceToCorner(const Eigen::Vector2d& p) const;

 private:
  const Scene& scene_;
  std::vector<Eigen::Vector2d> corners_;
};

}  // namespace scanfilter::sim
