#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Geometry>

#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

// The kept returns of one cached frame, looked up by world bearing: which of
// its beams passed a given world point, and what they returned. Kept for the
// free-space check (free_space_check.hpp). Returns the filter removed (a ghost
// through a pane, a mixed return) are stored as no return: they do not show
// where the beam's path was free. Floats: 40 frames of 3,600 beams each.
class RangeImage {
 public:
  // The two beams whose bearings bracket a point's, each with its lateral
  // neighbour on the far side (before, first, second, after in scan order),
  // and the point's distance from the sensor.
  struct Bracket {
    float before, first, second, after;
    double distance;
  };

  // `scan` placed where the filter put it: its pose under `correction`;
  // `labels` say which returns the filter kept.
  RangeImage(const Scan& scan, const SensorInfo& sensor, const Eigen::Isometry2d& correction,
             std::span<const std::uint8_t> labels);

  const Eigen::Vector2d& origin() const { return origin_; }
  // Nothing when p lies outside the scan's field of view (a partial turn) or
  // at the sensor.
  std::optional<Bracket> bracket(const Eigen::Vector2d& p) const;

 private:
  float at(std::int64_t i) const;  // NaN outside a partial turn; wraps on a full one

  Eigen::Vector2d origin_;
  double first_bearing_;  // world bearing of beam 0, rad
  double step_;           // signed world angle from one beam to the next, rad
  bool full_turn_;
  std::vector<float> ranges_;
};

}  // namespace scanfilter
