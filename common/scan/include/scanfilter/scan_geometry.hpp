#pragma once
#include <cassert>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

// +1 when the beam angle grows counter-clockwise with the index, else -1.
inline double directionSign(BeamDirection d) { return d == BeamDirection::kCcw ? 1.0 : -1.0; }

// Beam angle in the sensor frame (as the log stores it).
inline double beamAngle(const Scan& scan, std::size_t i) {
  return scan.angle_min + static_cast<double>(i) * scan.angle_increment;
}

// The sensor origin in the world frame: pose.xy + R(pose.theta) * mount.xy.
Eigen::Vector2d sensorOrigin(const Pose2& pose, const SensorMount& mount);

// World direction of beam i: pose.theta + mount.yaw + s * beam angle.
double beamWorldAngle(const Scan& scan, const SensorInfo& sensor, std::size_t i);

// World point of beam i at its range (the scan log format's formula).
Eigen::Vector2d beamToWorld(const Scan& scan, const SensorInfo& sensor, std::size_t i);

// The paper's equation (4): robot pose (x0, y0, θ0), sensor C metres behind the
// centre, zero direction θc, beam angle θp and range dis_p; angles grow clockwise.
Eigen::Vector2d paperEquation4(const Pose2& robot, double c, double theta_c, double theta_p,
                               double dis_p);

// Unit beam directions in the sensor frame (direction sign applied), kept
// between scans: a sensor's beam layout rarely changes, and recomputing 360
// sines and cosines per scan costs as much as the fast jump filter itself.
class BeamDirectionTable {
 public:
  const std::vector<Eigen::Vector2d>& directions(const Scan& scan, const SensorInfo& sensor);

 private:
  std::vector<Eigen::Vector2d> directions_;
  double angle_min_ = 0.0;
  double angle_increment_ = 0.0;
  double sign_ = 0.0;
};

// Points of one scan in the sensor's own frame, with the direction applied so
// that angles grow counter-clockwise: what the jump filter clusters on.
// Beams without a return get NaN coordinates.
void sensorFramePoints(const Scan& scan, const SensorInfo& sensor, BeamDirectionTable& table,
                       std::vector<Eigen::Vector2d>& out);

// World points of one scan; beams without a return get NaN coordinates.
void worldPoints(const Scan& scan, const SensorInfo& sensor, BeamDirectionTable& table,
                 std::vector<Eigen::Vector2d>& out);
void worldPoints(const Scan& scan, const SensorInfo& sensor, std::vector<Eigen::Vector2d>& out);

// The smallest box holding every point with a return (NaN points skipped);
// empty when there is none.
Eigen::AlignedBox2d returnBounds(std::span<const Eigen::Vector2d> points);

// a.x·b.y - a.y·b.x: the z of the cross product of two vectors of the plane
// (|a|·|b|·sin of the angle from a to b).
inline double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Angles in configuration files are degrees; the geometry works in radians.
inline constexpr double degreesToRadians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Distance of p from the line through a and b (from a when they coincide).
double distanceToLine(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b);
// Distance of p from the segment a-b (from a when they coincide).
double distanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// distanceToLine(p, a, b) > tolerance (>= 0), decided on squares: without
// its square root and division, which the filters' per-beam tests cannot
// afford. The two can disagree only where the distance is within a few ulp
// of the tolerance: each rounds its own way.
inline bool isFartherFromLineThan(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                  double tolerance) {
  assert(tolerance >= 0.0);
  const Eigen::Vector2d d = b - a;
  const double length_sq = d.squaredNorm();
  if (length_sq == 0.0) return (p - a).squaredNorm() > tolerance * tolerance;
  const double off = cross(d, p - a);  // |d| times p's distance from the line
  return off * off > tolerance * tolerance * length_sq;
}

// The direction of the surface at point i of a scan's points (world or sensor
// frame, NaN where no return): the chord from the return `span` beams before
// it to the one `span` beams after it (its neighbours by default), when both
// are returns and point i lies within `tolerance` of that chord, so one
// surface runs through all three. Unset at the ends of the scan, beside a
// missing return and where the three points bend (a corner, a depth step, a
// mixed return between two surfaces).
std::optional<Eigen::Vector2d> localSurfaceDirection(const std::vector<Eigen::Vector2d>& points, std::size_t i,
                                                     double tolerance, std::size_t span = 1);

// How many beams of `angle_step` (rad, either sign, non-zero) it takes to
// span `degrees` (> 0), rounded up: at least one, at most `beams` (so that a
// tiny step cannot overflow a count). An angle a whole number of steps wide
// up to rounding spans exactly that many.
std::size_t beamsSpanning(double degrees, double angle_step, std::size_t beams);

// True when the scan's beams cover a whole turn, so the first and last beams
// are neighbours (the seam).
bool isFullTurn(const Scan& scan);

}  // namespace scanfilter
