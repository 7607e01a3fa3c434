#include "scanfilter/mirror_ghost_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scanfilter {

bool MirrorGhostCheck::isGhost(const MirrorCrossing& crossing, const PenetrationGrid& grid) const {
  // The image first: its search is the smaller.
  return imageOnObstacle(crossing.image, grid) && (crossing.within_segment || lineGoesOn(crossing, grid));
}

bool MirrorGhostCheck::lineGoesOn(const MirrorCrossing& crossing, const PenetrationGrid& grid) const {
  const Eigen::Vector2d normal(-crossing.unit.y(), crossing.unit.x());
  const double reach = params_.line_window + params_.line_tolerance;
  const Eigen::Vector2d corner(reach, reach);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  // Any cell holding a return counts: a mirror's diffuse returns are single.
  return grid.anyCellHoldingIn(grid.cellOf(crossing.at - corner), grid.cellOf(crossing.at + corner), 1,
                               [&](CellIndex c) {
                                 const Eigen::Vector2d offset = grid.centroid(c) - crossing.at;
                                 const double along = crossing.unit.dot(offset);
                                 if (std::abs(normal.dot(offset)) <= params_.line_tolerance &&
                                     std::abs(along) <= params_.line_window) {
                                   lo = std::min(lo, along);
                                   hi = std::max(hi, along);
                                 }
                                 return hi - lo >= params_.line_spread;
                               });
}

bool MirrorGhostCheck::imageOnObstacle(const Eigen::Vector2d& image, const PenetrationGrid& grid) const {
  const double r = params_.image_radius;
  const Eigen::Vector2d corner(r, r);
  return grid.anyObstacleIn(grid.cellOf(image - corner), grid.cellOf(image + corner), [&](CellIndex c) {
    return (grid.centroid(c) - image).squaredNorm() <= r * r;
  });
}

}  // namespace scanfilter
