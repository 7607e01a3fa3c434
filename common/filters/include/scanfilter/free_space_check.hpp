#pragma once
#include <Eigen/Core>

#include "scanfilter/penetration_filter_params.hpp"
#include "scanfilter/range_image.hpp"

namespace scanfilter {

// Beyond the paper: is a return in space that other viewpoints saw through?
//
// A return on a real surface blocks the beams of every other viewpoint that
// looks its way: they end at it. A mixed return (the footprint straddling an
// edge) or a displaced one lies in free space between surfaces, where
// cached frames taken from elsewhere looked straight through. The caller
// tests only returns beside a depth edge (nearSideOfDepthEdge): that is where
// mixed returns are. Parameters: free_space_margin (+ free_space_margin_per_m
// of p's distance from the frame's sensor), free_space_dip,
// free_space_min_frames.
//
// A cached frame passed through point p when the two beams that bracket p's
// bearing and the one outside each of them all returned farther than p by
// the margin (a beam of pose error between the frames must not make an edge
// point look passed through), and neither bracketing beam is the dip shorter
// than the outer ones: a thin leg standing partly in a beam (a triangulation
// scanner's beam sweeps a whole step, a time-of-flight beam is wider than a
// step) pulls the return short of the background without ending it at the
// leg, and is not counted as passed through. A frame hit p when either
// bracketing beam ended within the margin of it.
class FreeSpaceCheck {
 public:
  enum class Sighting { kNone, kThrough, kHit };

  explicit FreeSpaceCheck(const PenetrationFilterParams& params)
      : margin_(params.free_space_margin),
        margin_per_m_(params.free_space_margin_per_m),
        dip_(params.free_space_dip),
        min_frames_(params.free_space_min_frames) {}

  // What one cached frame's beams say about point p.
  Sighting sighting(const RangeImage& frame, const Eigen::Vector2d& p) const;

  // The verdict over the frames' sightings.
  bool seenThrough(int through, int hits) const { return through >= min_frames_ && through > hits; }

 private:
  double margin_;        // m
  double margin_per_m_;  // m per m of p's distance from the frame's sensor
  double dip_;           // m
  int min_frames_;
};

}  // namespace scanfilter
