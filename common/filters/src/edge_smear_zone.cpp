#include "scanfilter/edge_smear_zone.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scanfilter/cell_key.hpp"

namespace scanfilter {

std::int32_t EdgeSmearZone::bucketCoordinate(double v) const {
  constexpr double kLimit = std::numeric_limits<std::int32_t>::max() - 1;
  return static_cast<std::int32_t>(std::clamp(std::floor(v / radius_), -kLimit, kLimit));
}

void EdgeSmearZone::build(std::span<const Eigen::Vector2d> ends, double radius) {
  radius_ = radius;
  ends_.clear();
  if (!(radius > 0.0)) return;
  for (const auto& p : ends)
    if (p.allFinite()) ends_.push_back({cellKey(bucketCoordinate(p.x()), bucketCoordinate(p.y())), p});
  std::sort(ends_.begin(), ends_.end(), [](const End& a, const End& b) { return a.bucket < b.bucket; });
}

bool EdgeSmearZone::contains(const Eigen::Vector2d& q) const {
  if (ends_.empty() || !q.allFinite()) return false;
  const double radius_sq = radius_ * radius_;
  const std::int32_t bx = bucketCoordinate(q.x());
  const std::int32_t by = bucketCoordinate(q.y());
  // An end within the radius lies in one of the 3 x 3 buckets around q's.
  for (std::int32_t dx = -1; dx <= 1; ++dx) {
    for (std::int32_t dy = -1; dy <= 1; ++dy) {
      const std::uint64_t key = cellKey(bx + dx, by + dy);
      auto it = std::lower_bound(ends_.begin(), ends_.end(), key,
                                 [](const End& e, std::uint64_t k) { return e.bucket < k; });
      for (; it != ends_.end() && it->bucket == key; ++it)
        if ((it->position - q).squaredNorm() <= radius_sq) return true;
    }
  }
  return false;
}

}  // namespace scanfilter
