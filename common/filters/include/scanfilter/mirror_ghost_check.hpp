#pragma once
#include <Eigen/Core>

#include "scanfilter/penetration_grid.hpp"

namespace scanfilter {

// Parameters of the mirror-image test (config/filter.yaml, penetration_filter:
// surface_memory: mirror_ghosts, documents each; docs/accuracy.md, Beyond the
// paper 35).
struct MirrorGhostParams {
  bool enabled = true;
  double image_radius = 0.08;    // m, the image lies this near an obstacle the cache holds
  double line_window = 0.30;     // m, past a mirror's remembered ends: the cache's returns this near the crossing ...
  double line_tolerance = 0.04;  // m, ... and this near the mirror's line ...
  double line_spread = 0.10;     // m, ... spread this far along it show that the mirror goes on there
};

// Where the beam to a return crossed the line of a remembered pane or
// mirror, the return lying beyond that line (SurfaceMemory::anyMirrorBehind).
struct MirrorCrossing {
  Eigen::Vector2d at;      // the crossing, on the line
  Eigen::Vector2d unit;    // the line's direction
  Eigen::Vector2d image;   // the return mirrored across the line
  bool within_segment;     // the crossing lies on the remembered stretch
};

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
// returns along its line (a glossy surface's occasional diffuse returns, a
// pane's): returns spread along the line, not a wall that crosses it,
// which holds returns at one place only. Without that, the image of a wall
// that meets the line at right angles is that wall itself, and the rooms
// of a building mirror each other across their walls.
class MirrorGhostCheck {
 public:
  explicit MirrorGhostCheck(const MirrorGhostParams& params) : params_(params) {}

  bool enabled() const { return params_.enabled; }
  // Whether the return whose beam crossed a mirror so is a ghost: the
  // mirror is there (the remembered stretch, or a line the cache's returns
  // continue it along) and the image lies on an obstacle of `grid`.
  bool isGhost(const MirrorCrossing& crossing, const PenetrationGrid& grid) const;

 private:
  bool lineGoesOn(const MirrorCrossing& crossing, const PenetrationGrid& grid) const;
  bool imageOnObstacle(const Eigen::Vector2d& image, const PenetrationGrid& grid) const;

  MirrorGhostParams params_;
};

}  // namespace scanfilter
