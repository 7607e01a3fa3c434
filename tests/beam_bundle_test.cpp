// The fast step 2 walks neighbouring beams once, in one band around an axis:
// that band must hold every point within the beam half width of any of the
// beams, or a cell a beam's own walk would test is missed.
#include "scanfilter/beam_bundle.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace scanfilter {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

BundledBeam beamAt(double angle_rad, double reach) { return {{std::cos(angle_rad), std::sin(angle_rad)}, reach}; }

// Distance from q to the segment origin (0, 0) -> axis * length.
double distanceToAxis(const BundleBand& band, const Eigen::Vector2d& q) {
  const double t = std::clamp(q.dot(band.axis), 0.0, band.length);
  return (q - band.axis * t).norm();
}

TEST(BundleBand, OneBeamIsItsOwnBand) {
  const BundledBeam beam = beamAt(30 * kDeg, 4.0);
  const auto band = bundleBand(std::vector{beam}, 0.1);
  ASSERT_TRUE(band);
  EXPECT_NEAR((band->axis - beam.unit).norm(), 0.0, 1e-12);
  EXPECT_NEAR(band->length, 4.0, 1e-8);
  EXPECT_NEAR(band->half_width, 0.1, 1e-8);
}

TEST(BundleBand, WidensByHowFarTheOuterBeamsLeaveTheAxis) {
  // Beams at -1°, 0°, +1°, 5 m: the outer ones end 5·sin(1°) off the axis.
  const std::vector beams{beamAt(-1 * kDeg, 5.0), beamAt(0.0, 5.0), beamAt(1 * kDeg, 5.0)};
  const auto band = bundleBand(beams, 0.075);
  ASSERT_TRUE(band);
  EXPECT_NEAR(band->half_width, 0.075 + 5.0 * std::sin(1 * kDeg), 1e-8);
  EXPECT_NEAR(band->length, 5.0, 1e-8);
  EXPECT_NEAR(fanSpread(beams.front(), beams.back(), 5.0), 5.0 * std::sin(1 * kDeg), 1e-12);
}

TEST(BundleBand, NoBandForBeamsFarOffTheAxis) {
  EXPECT_FALSE(bundleBand(std::vector{beamAt(0.0, 1.0), beamAt(130 * kDeg, 1.0)}, 0.1));
  EXPECT_TRUE(std::isinf(fanSpread(beamAt(0.0, 1.0), beamAt(130 * kDeg, 1.0), 1.0)));
  // A beam between two close ones but pointing elsewhere (not a run of one scan).
  EXPECT_FALSE(bundleBand(std::vector{beamAt(0.0, 1.0), beamAt(90 * kDeg, 1.0), beamAt(1 * kDeg, 1.0)}, 0.1));
}

// Random fans of beams, random points near them: every point within the
// half width of a beam lies within the band.
TEST(BundleBand, HoldsEveryPointNearAnyOfItsBeams) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int checked = 0;
  for (int fan = 0; fan < 2000; ++fan) {
    const double start = 2 * std::numbers::pi * u(rng);
    const double step = (u(rng) < 0.5 ? -1 : 1) * (0.05 + 2.0 * u(rng)) * kDeg;
    const int n = 1 + static_cast<int>(u(rng) * 20);
    const double half_width = 0.01 + 0.2 * u(rng);
    std::vector<BundledBeam> beams;
    for (int k = 0; k < n; ++k) beams.push_back(beamAt(start + k * step, 0.05 + 12.0 * u(rng)));
    const auto band = bundleBand(beams, half_width);
    if (!band) continue;
    for (int sample = 0; sample < 20; ++sample) {
      const BundledBeam& beam = beams[static_cast<std::size_t>(u(rng) * n)];
      // A point on the beam, then pushed up to half_width in any direction.
      const double angle = 2 * std::numbers::pi * u(rng);
      const Eigen::Vector2d q = beam.unit * (beam.reach * u(rng)) +
                                half_width * u(rng) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      ASSERT_LE(distanceToAxis(*band, q), band->half_width) << "fan " << fan << " sample " << sample;
      ++checked;
    }
  }
  EXPECT_GT(checked, 30000);
}

}  // namespace
}  // namespace scanfilter
