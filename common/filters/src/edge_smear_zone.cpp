#include "scanfilter/edge_smear_zone.hpp"

namespace scanfilter {

void EdgeSmearZone::build(std::span<const Eigen::Vector2d> ends, double radius) {
  radius_ = radius;
  ends_.clear();
  if (!(radius > 0.0)) return;
  for (const auto& p : ends)
    if (p.allFinite()) ends_.push_back({bucketOf(bucketCoordinate(p.x()), bucketCoordinate(p.y())), p});
  std::sort(ends_.begin(), ends_.end(), [](const End& a, const End& b) { return a.bucket < b.bucket; });
}

}  // namespace scanfilter
