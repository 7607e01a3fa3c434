#include "scanfilter/mirror_ghost_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scanfilter {

bool MirrorGhostCheck::isGhost(const MirrorCrossing& crossing, const PenetrationGrid& grid) const {
  // The image first: its search is the smaller.
  return imageOnObstacle(crossing.image, grid) && mirrorThere(crossing, grid);
}

bool MirrorGhostCheck::seenThroughProven(const MirrorCrossing& crossing, const std::vector<bool>& proven,
                                         const PenetrationGrid& grid) const {
  return crossing.surface < proven.size() && proven[crossing.surface] && mirrorThere(crossing, grid);
}

bool MirrorGhostCheck::mirrorThere(const MirrorCrossing& crossing, const PenetrationGrid& grid) const {
  return crossing.within_segment || lineGoesOn(crossing, grid);
}

bool MirrorGhostCheck::mirrorWithin(const MirrorCrossing& crossing, const PenetrationGrid& grid, double reach) const {
  return crossing.past_end <= reach || mirrorThere(crossing, grid);
}

bool MirrorGhostCheck::lineGoesOn(const MirrorCrossing& crossing, const PenetrationGrid& grid) const {
  const ReturnsNearLine near = returnsNearLine(crossing, grid);
  // A return on the line with one just off it a cell along or less is a
  // surface crossing the line there, not the mirror.
  const auto crossedThere = [&](double along) {
    return std::any_of(near.beside_line.begin(), near.beside_line.end(),
                       [&](double beside) { return std::abs(beside - along) <= grid.cellSize(); });
  };
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double along : near.on_line) {
    if (crossedThere(along)) continue;
    lo = std::min(lo, along);
    hi = std::max(hi, along);
  }
  return lo < 0.0 && hi > 0.0 && hi - lo >= params_.line_spread;
}

MirrorGhostCheck::ReturnsNearLine MirrorGhostCheck::returnsNearLine(const MirrorCrossing& crossing,
                                                                    const PenetrationGrid& grid) const {
  const Eigen::Vector2d normal(-crossing.unit.y(), crossing.unit.x());
  const double reach = params_.line_window + params_.crossing_band;
  const Eigen::Vector2d corner(reach, reach);
  ReturnsNearLine near;
  // Every cell holding a return counts: a mirror's diffuse returns are single.
  grid.anyCellHoldingIn(grid.cellOf(crossing.at - corner), grid.cellOf(crossing.at + corner), kAnyReturn,
                        [&](CellIndex c) {
                          const Eigen::Vector2d offset = grid.centroid(c) - crossing.at;
                          const double along = crossing.unit.dot(offset), off = std::abs(normal.dot(offset));
                          if (std::abs(along) > params_.line_window) return false;
                          if (off <= params_.line_tolerance) near.on_line.push_back(along);
                          else if (off <= params_.crossing_band) near.beside_line.push_back(along);
                          return false;  // visit them all
                        });
  return near;
}

bool MirrorGhostCheck::imageOnObstacle(const Eigen::Vector2d& image, const PenetrationGrid& grid) const {
  const double r = params_.image_radius;
  const Eigen::Vector2d corner(r, r);
  return grid.anyObstacleIn(grid.cellOf(image - corner), grid.cellOf(image + corner), [&](CellIndex c) {
    return (grid.centroid(c) - image).squaredNorm() <= r * r;
  });
}

}  // namespace scanfilter
