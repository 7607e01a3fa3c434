#pragma once
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
// (edge_smear_radius; docs/beyond-the-paper.md, 22).
class EdgeSmearZone {
 public:
  // Replaces the zone: discs of `radius` around `ends` (the non-finite
  // ones left out). radius <= 0: an empty zone.
  void build(std::span<const Eigen::Vector2d> ends, double radius);
  // Whether an end lies within the radius of q (on the circle counts).
  bool contains(const Eigen::Vector2d& q) const;

 private:
  struct End {
    std::uint64_t bucket;
    Eigen::Vector2d position;
  };
  // Bucket coordinate of a finite position: radius-wide squares. Clamped one
  // inside the int32 range, so that no radius or position can overflow it
  // or its neighbours (positions that far apart are never within a radius
  // anyway).
  std::int32_t bucketCoordinate(double v) const;
  double radius_ = 0.0;
  std::vector<End> ends_;  // sorted by bucket
};

}  // namespace scanfilter
