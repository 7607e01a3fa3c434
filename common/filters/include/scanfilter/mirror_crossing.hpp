#pragma once
#include <cstddef>

#include <Eigen/Core>

namespace scanfilter {

// Where the beam to a return crossed the line of a remembered pane or
// mirror, the return lying beyond that line (SurfaceMemory::anyMirrorCrossed).
struct MirrorCrossing {
  Eigen::Vector2d at;      // the crossing, on the line
  Eigen::Vector2d unit;    // the line's direction
  Eigen::Vector2d image;   // the return mirrored across the line
  bool within_segment;     // the crossing lies on the remembered stretch, inside its end margins
  // Which remembered pane or mirror: the same number for every crossing of
  // it while the memory is unchanged (a frame's judging), not beyond.
  std::size_t surface = 0;
  // How far past the nearer end of the remembered stretch the crossing lies
  // (m; 0 or less on it, end margins included).
  double past_end = 0.0;
};

}  // namespace scanfilter
