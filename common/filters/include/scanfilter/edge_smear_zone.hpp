#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace scanfilter {

// Where the frame being judged sees surfaces end: discs of radius R around
// the ends, looked up by position. Cached returns fringe a surface's end
// by several centimetres (a footprint straddling the edge mixes the near
// range with the far one, each viewpoint elsewhere; pose error), and a beam
// passing just beside the end would seem to cross the surface, though the
// frame shows it ending there. Step 2 counts no obstacle in the discs
// (edge_smear_radius; docs/accuracy.md, Beyond the paper 22).
class EdgeSmearZone {
 public:
  // Replaces the zone: discs of `radius` around `ends`. radius <= 0 or no
  // ends: an empty zone.
  void build(std::span<const Eigen::Vector2d> ends, double radius);
  bool empty() const { return ends_.empty(); }
  // Whether q lies within the radius of an end (on the circle counts).
  bool contains(const Eigen::Vector2d& q) const {
    return anyEndNear(q, [](const Eigen::Vector2d&) { return true; });
  }
  // Calls stop(end) for the ends within the radius of q (on the circle
  // counts) until it returns true; whether it did.
  template <typename Stop>
  bool anyEndNear(const Eigen::Vector2d& q, Stop&& stop) const;

 private:
  struct End {
    std::uint64_t bucket;
    Eigen::Vector2d position;
  };
  // Bucket coordinates of a finite position; the zone only ever holds
  // returns within a scanner's range, far inside int32.
  std::int64_t bucketCoordinate(double v) const { return static_cast<std::int64_t>(std::floor(v / radius_)); }
  static std::uint64_t bucketOf(std::int64_t bx, std::int64_t by) {
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(bx)) << 32) | static_cast<std::uint32_t>(by);
  }
  double radius_ = 0.0;
  std::vector<End> ends_;  // sorted by bucket: buckets are radius-wide squares
};

template <typename Stop>
bool EdgeSmearZone::anyEndNear(const Eigen::Vector2d& q, Stop&& stop) const {
  if (ends_.empty() || !q.allFinite()) return false;
  const double radius_sq = radius_ * radius_;
  const std::int64_t bx = bucketCoordinate(q.x());
  const std::int64_t by = bucketCoordinate(q.y());
  // An end within the radius lies in one of the 3 x 3 buckets around q's.
  for (std::int64_t dx = -1; dx <= 1; ++dx) {
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      const std::uint64_t key = bucketOf(bx + dx, by + dy);
      auto it = std::lower_bound(ends_.begin(), ends_.end(), key,
                                 [](const End& e, std::uint64_t k) { return e.bucket < k; });
      for (; it != ends_.end() && it->bucket == key; ++it)
        if ((it->position - q).squaredNorm() <= radius_sq && stop(it->position)) return true;
    }
  }
  return false;
}

}  // namespace scanfilter
