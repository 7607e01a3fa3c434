#pragma once
// Bounds on what a scan's numbers can be, for input from outside (logs, the
// wire). The filters and the map turn points into integer grid cells; a
// coordinate beyond these (1e181 m came from a fuzzed sample) does not fit
// an int and is corrupt data anyway, so it is rejected where it enters.

#include <cmath>
#include <numbers>

namespace scanfilter {

// Largest believable range (m): no indoor LiDAR measures 10 km.
inline constexpr double kMaxPlausibleRange = 1.0e4;
// Largest believable pose or mount coordinate (m): 1000 km from the map's
// origin; at the finest map cell (5 mm) that is 2e8 cells, inside an int.
inline constexpr double kMaxPlausibleCoordinate = 1.0e6;

inline bool isPlausibleCoordinate(double v) { return v >= -kMaxPlausibleCoordinate && v <= kMaxPlausibleCoordinate; }

// Largest believable first-beam angle (rad, two turns either way) and step
// (rad, 90°: the bound on Δθ). Beyond them angle_min + i·step can overflow to
// infinity (a fuzzed sample had a step of 1.2e307 rad) and cos(inf) is NaN.
inline constexpr double kMaxPlausibleAngle = 4.0 * std::numbers::pi;
inline constexpr double kMaxPlausibleAngleStep = std::numbers::pi / 2.0;

inline bool isPlausibleBeamGeometry(double angle_min, double angle_increment) {
  return std::abs(angle_min) <= kMaxPlausibleAngle && std::abs(angle_increment) <= kMaxPlausibleAngleStep;
}

}  // namespace scanfilter
