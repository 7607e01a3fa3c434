// returnsAtGrazingIncidence: which returns of a scan meet their surface at a
// shallow angle, against the geometry of a wall seen from a known place.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "scanfilter/grazing_returns.hpp"

namespace scanfilter {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// A scan of the wall y = 1 from the origin, beams every `step` from 1° to
// 179°: the beam at bearing a meets the wall at an angle of a (or 180° - a).
std::vector<Eigen::Vector2d> wallScan(double step) {
  std::vector<Eigen::Vector2d> points;
  for (double a = 1.0 * kDeg; a < 179.0 * kDeg; a += step) points.emplace_back(std::cos(a) / std::sin(a), 1.0);
  return points;
}

double bearingDeg(const Eigen::Vector2d& p) { return std::atan2(p.y(), p.x()) / kDeg; }

TEST(GrazingReturns, MarksTheReturnsWhoseBeamMeetsTheWallAtLessThanTheAngle) {
  for (const double step_deg : {1.0, 0.1}) {
    const auto points = wallScan(step_deg * kDeg);
    const BeamMask grazing = returnsAtGrazingIncidence(points, Eigen::Vector2d::Zero(), step_deg * kDeg, 10.0, 0.01);
    // The first and last beams have no chord over kSurfaceSpanDeg.
    const auto span = static_cast<std::size_t>(std::lround(kSurfaceSpanDeg / step_deg));
    int marked = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double angle = std::min(bearingDeg(points[i]), 180.0 - bearingDeg(points[i]));
      const bool has_chord = i >= span && i + span < points.size();
      // Half a degree either side of 10° the chord's direction may round either way.
      if (angle < 9.5 && has_chord) {
        EXPECT_TRUE(grazing[i]) << "beam at " << angle << "° (step " << step_deg << "°)";
      }
      if (angle > 10.5) {
        EXPECT_FALSE(grazing[i]) << "beam at " << angle << "° (step " << step_deg << "°)";
      }
      marked += grazing[i];
    }
    EXPECT_GT(marked, 0) << "step " << step_deg << "°";
  }
}

TEST(GrazingReturns, OffAtZeroAndNothingWithoutOneSurfaceThroughTheReturn) {
  auto points = wallScan(1.0 * kDeg);
  const BeamMask off_at_zero = returnsAtGrazingIncidence(points, Eigen::Vector2d::Zero(), 1.0 * kDeg, 0.0, 0.01);
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_FALSE(off_at_zero[i]);
  // A return 5 cm off its neighbours' chord, and one beside a missing return:
  // neither has a surface.
  const std::size_t off = 3, beside_gap = 6;
  points[off].y() += 0.05;
  points[beside_gap + 1] = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  const BeamMask grazing = returnsAtGrazingIncidence(points, Eigen::Vector2d::Zero(), 1.0 * kDeg, 10.0, 0.01);
  EXPECT_FALSE(grazing[off]);
  EXPECT_FALSE(grazing[beside_gap]);
  EXPECT_TRUE(grazing[5]) << "a beam at 6° with its surface intact";
}

}  // namespace
}  // namespace scanfilter
