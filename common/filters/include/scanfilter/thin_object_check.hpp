#pragma once
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/scan.hpp"

namespace scanfilter {

// Beyond the paper (docs/beyond-the-paper.md, 25): the mixed return
// of an object thinner than the beam's footprint, a chair or table leg. The
// footprint falls partly on the object and partly on the background behind
// it, and the sensor reports a range between the two: beside the object's
// own returns, in front of the background on both sides, far from any
// surface. A real thin leg looks the same in one scan, so step 1 keeps it
// (keep_foreground_clusters). The cache tells them apart: when a cell of it
// holding thin_object_min_returns (1 at 1°; fewer than an obstacle needs:
// most of a thin leg's returns are mixed and land elsewhere, Beyond the
// paper 32) puts an object on the beam,
// more than a depth step in front of the return and close enough to the
// beam's axis to lie in its footprint, the beam's light came partly from
// that object, and the return lies where nothing is. Step 2 spares a return
// the rescue's evidence vouches for (returns seen from elsewhere where it
// lies): a chair's rear leg, partly behind its front one. Beside a beam
// without a return (nothing within range behind there), the mix needs a
// second object in the footprint behind the return (Beyond the paper 30).
class ThinObjectCheck {
 public:
  // depth_step: how much nearer than the return the object must be (and how
  // much farther both neighbours are: a depth edge, not a surface's noise);
  // object_radius: how far an object's position (the mean of its cached
  // returns, or its cell's centre without obstacle_at_centroid) may lie from
  // the edge of the footprint it reaches into.
  ThinObjectCheck(double depth_step, double object_radius)
      : depth_step_(depth_step), object_radius_(object_radius) {}

  // The footprint is taken as one angular step wide: a triangulation
  // scanner sweeps its spot over the step while it measures, and beams
  // placed a step apart leave no gaps. A time-of-flight spot is wider than
  // its step, so some of its mixed returns are missed. The step's sign (the
  // beams' direction) does not matter.
  double halfWidthAt(double distance, double angle_step) const {
    return object_radius_ + 0.5 * distance * std::abs(angle_step);
  }

  // Whether a cached object at q, seen from `origin`, lies in the footprint
  // of the beam to p, in front of p by more than the depth step.
  bool inFootprintInFront(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                          double angle_step) const;
  // Whether it lies in that footprint behind p by more than the depth step,
  // and no farther than `reach` from the sensor (the sensor's range: the
  // light of anything beyond is too weak to pull a range back).
  bool inFootprintBehind(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                         double angle_step, double reach) const;

  // How far short of p (or past it) along its beam an object must lie.
  double depthStep() const { return depth_step_; }

 private:
  struct AlongBeam {
    double along;   // m from the sensor to q's foot on the beam
    double length;  // m from the sensor to p
  };
  // Where q lies along the beam from `origin` to p, when it lies within the
  // footprint there, in front of the sensor.
  std::optional<AlongBeam> alongInFootprint(const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                                            const Eigen::Vector2d& q, double angle_step) const;

  double depth_step_;     // m
  double object_radius_;  // m
};

// How a return stands against the beams beside the stretch it belongs to.
enum class StandsInFront : std::uint8_t {
  kNo,
  // Both beams beside it return farther: the background the footprint's
  // rest fell on is there, on either side.
  kOfBothSides,
  // One of them or both return nothing (the other farther): no background
  // within range there, so a mixed return needs a second object in the
  // footprint, behind the return (a chair's rear leg behind its front one).
  kBesideNoReturn,
};

// Returns standing in front: every stretch of at most `max_beams` returns
// whose neighbouring beams on both sides return farther than the stretch's
// farthest return by more than `depth_step`, or nothing. The stretch holds
// a thin object's own returns and its mixed ones beside them (the leg at
// 1 m and, next to it, a mix of the leg and the wall behind at 2 m: both
// stand in front of the wall on either side). A wall's end is no such
// stretch: the wall goes on for more than a few beams. A return in stretches
// of both kinds is kOfBothSides. On a full turn stretches run across the
// seam; on a partial one a stretch at either end is not flagged (one side is
// unknown).
std::vector<StandsInFront> standingInFront(const Scan& scan, std::size_t max_beams, double depth_step);

}  // namespace scanfilter
