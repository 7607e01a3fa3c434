#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Geometry>

#include "scanfilter/stamp.hpp"

namespace scanfilter {

// A robot base pose in the world frame.
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;

  Eigen::Isometry2d isometry() const {
    Eigen::Isometry2d iso = Eigen::Isometry2d::Identity();
    iso.translate(Eigen::Vector2d(x, y));
    iso.rotate(theta);
    return iso;
  }
};

// One 2D scan with the robot pose at its stamp. Ranges that are not a return
// (missing, zero, NaN, outside the sensor's limits) are stored as NaN so the
// filters see one representation of "no return"; the values the source gave
// (+inf, an out-of-limit reading, ...) are kept beside them, because a beam the
// filter keeps must leave exactly as it came (REP 117).
struct Scan {
  Stamp stamp;
  Pose2 pose;
  double angle_min = 0.0;
  double angle_increment = 0.0;
  std::vector<double> ranges;
  std::vector<double> recorded_ranges;       // as the source gave them; empty: equal to `ranges`
  std::vector<double> intensities;           // empty when the log has none
  std::vector<std::uint8_t> truth;           // empty when unlabelled
  std::vector<std::uint8_t> labels;          // empty until a filter ran
  std::vector<std::uint32_t> thin_leg_beams;  // simulator ground truth: beams hitting a thin leg
  std::vector<std::uint8_t> truth_cause;     // simulator ground truth: ArtefactCause per beam; empty: unknown

  std::size_t size() const { return ranges.size(); }
  bool hasReturn(std::size_t i) const { return ranges[i] == ranges[i]; }  // not NaN
  std::span<const double> rangesAsRecorded() const { return recorded_ranges.empty() ? ranges : recorded_ranges; }
};

}  // namespace scanfilter
