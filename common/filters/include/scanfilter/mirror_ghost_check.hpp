#pragma once
#include <vector>

#include <Eigen/Core>

#include "scanfilter/mirror_crossing.hpp"
#include "scanfilter/mirror_ghost_params.hpp"
#include "scanfilter/penetration_grid.hpp"

namespace scanfilter {

// Beyond the paper 35: a ghost is the mirror image of a real surface. A
// beam that meets a mirror goes on, reflected, to a surface on the sensor's
// side; the sensor puts the return on the beam's first line, as far as the
// light travelled, which is exactly that surface mirrored across the
// mirror's line. So a return beyond a known mirror's line whose image
// lies on an obstacle the cache holds is that surface's ghost.
//
// The test reaches past the stretch of the mirror the memory holds: a
// mirror returns the beam only near normal incidence, so most of it is
// never seen, while its ghosts are. It goes on where the cache holds
// returns along its line on both sides of the crossing (a glossy surface's
// occasional diffuse returns, a pane's), and not where those returns are a
// surface that crosses the line: one with returns just off the line beside
// them (crossing_band), a wall, or a box's face ending beside a wall.
// Without that, the image of a wall that meets the line at right angles is
// that wall itself, and the rooms of a building mirror each other across
// their walls.
//
// Beyond the paper 43: a ghost the test finds proves that its pane or
// mirror reflects the beam now, from where the frame was taken. Every other
// return of that frame beyond it, where it is there, was reflected by it or
// passed through it (a pane's transmitted returns are real surfaces: their
// images lie on nothing). Without a ghost, a remembered line with the
// cache's returns along it could be a wall's edge or a doorway's jamb.
class MirrorGhostCheck {
 public:
  explicit MirrorGhostCheck(const MirrorGhostParams& params) : params_(params) {}

  bool enabled() const { return params_.enabled; }
  // How far beyond the mirror's line a return must lie to be tested:
  // nearer, its image (as near on the other side) could fall within
  // image_radius of the mirror's own returns, which scatter about its line
  // (noise), or of the return's own surface seen just beyond the line.
  double minDepthBeyondLine() const { return 2.0 * params_.image_radius; }
  // Whether the return whose beam crossed a mirror so is a ghost: the
  // mirror is there (the remembered stretch, or a line the cache's returns
  // continue it along) and the image lies on an obstacle of `grid`.
  bool isGhost(const MirrorCrossing& crossing, const PenetrationGrid& grid) const;
  // Whether the frame's other returns beyond a mirror it found a ghost in go too (43).
  bool marksBeyondProvenMirrors() const { return params_.enabled && params_.beyond_proven_mirrors; }
  // Whether the mirror is there where the beam crossed its line: on the
  // remembered stretch, or where the cache's returns continue it.
  bool mirrorThere(const MirrorCrossing& crossing, const PenetrationGrid& grid) const;
  // Whether it is there, or the crossing lies at most `reach` past the
  // remembered stretch: a pane's ends are met more obliquely than its
  // middle, so the stretch the memory holds falls short of them (44).
  bool mirrorWithin(const MirrorCrossing& crossing, const PenetrationGrid& grid, double reach) const;
  // Whether the beam went through a mirror the frame found a ghost in
  // (proven[crossing.surface]) where that mirror is there (43).
  bool seenThroughProven(const MirrorCrossing& crossing, const std::vector<bool>& proven,
                         const PenetrationGrid& grid) const;

 private:
  bool lineGoesOn(const MirrorCrossing& crossing, const PenetrationGrid& grid) const;
  // The cached returns within line_window of the crossing along the line:
  // how far along it each lies, split by how far off it.
  struct ReturnsNearLine {
    std::vector<double> on_line;      // within line_tolerance
    std::vector<double> beside_line;  // farther, within crossing_band
  };
  ReturnsNearLine returnsNearLine(const MirrorCrossing& crossing, const PenetrationGrid& grid) const;
  bool imageOnObstacle(const Eigen::Vector2d& image, const PenetrationGrid& grid) const;

  MirrorGhostParams params_;
  static constexpr int kAnyReturn = 1;  // a cell holding this many returns or more is searched
};

}  // namespace scanfilter
