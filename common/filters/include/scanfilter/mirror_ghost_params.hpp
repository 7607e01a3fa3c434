#pragma once

namespace scanfilter {

// Parameters of the mirror-image test (config/filter.yaml, penetration_filter:
// surface_memory: mirror_ghosts, documents each;
// docs/beyond-the-paper.md, 35).
struct MirrorGhostParams {
  bool enabled = true;
  double image_radius = 0.08;    // m, the image lies this near an obstacle the cache holds
  double line_window = 0.30;     // m, past a mirror's remembered ends: the cache's returns this near the crossing ...
  double line_tolerance = 0.04;  // m, ... and this near the mirror's line ...
  double line_spread = 0.10;     // m, ... spread this far along it, on both sides, show that the mirror goes on
  double crossing_band = 0.12;   // m, a return this near the line beside a line return: a surface crossing it there
  // Beyond the paper 43: a pane or mirror a frame sees a ghost in reflects
  // now, and the frame's returns beyond it where it is there go too.
  bool beyond_proven_mirrors = true;
};

}  // namespace scanfilter
