// The range-noise estimate of step 1 (Beyond the paper 18): σ(d) measured on
// scans of a known noise, the configured model as the floor, the bands that
// do not count, and what it changes in the jump filter.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "scan_builder.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/range_noise_estimate.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {
namespace {

using test::castScan;
using test::World;

constexpr double kRoomHalfWidth = 6.0;  // m: ranges from 6 to 8.5 m from the middle ...
constexpr double kOffCentre = 4.5;      // m: ... and from 1.5 m up when the sensor stands off centre

World squareRoom() {
  const double h = kRoomHalfWidth;
  World w;
  w.wall({-h, -h}, {h, -h}).wall({h, -h}, {h, h}).wall({h, h}, {-h, h}).wall({-h, h}, {-h, -h});
  return w;
}

SensorInfo sensor() {
  SensorInfo s;
  s.range_min = 0.1;
  s.range_max = 12.0;
  return s;
}

// Scans of the room from a few places, ranges perturbed by σ(d) = base + quadratic·d².
std::vector<Scan> noisyScans(double base, double quadratic, int count, std::uint32_t seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<Scan> scans;
  for (int k = 0; k < count; ++k) {
    const double x = kOffCentre * std::cos(0.7 * k), y = kOffCentre * std::sin(0.7 * k) * 0.5;
    Scan scan = castScan(squareRoom(), {x, y, 0.1 * k}, sensor(), 720);
    for (double& r : scan.ranges)
      if (std::isfinite(r)) r += (base + quadratic * r * r) * normal(rng);
    scans.push_back(std::move(scan));
  }
  return scans;
}

// Smoothed over many scans, so that the figures below are tight.
JumpFilterParams params(double base, double quadratic) {
  JumpFilterParams p;
  p.noise_sigma_base = base;
  p.noise_sigma_quadratic = quadratic;
  p.d_max = sensor().range_max;
  p.noise_estimate_window_scans = 200;
  p.noise_estimate_min_samples = 100;
  return p;
}

RangeNoiseEstimate estimateOf(const std::vector<Scan>& scans, const JumpFilterParams& p) {
  RangeNoiseEstimate estimate(p);
  BeamDirectionTable directions;
  std::vector<Eigen::Vector2d> points;
  for (const Scan& scan : scans) {
    sensorFramePoints(scan, sensor(), directions, points);
    estimate.add(points, scan.ranges, true);
  }
  return estimate;
}

TEST(RangeNoiseEstimate, MeasuresAConstantNoise) {
  const RangeNoiseModel m = estimateOf(noisyScans(0.012, 0.0, 60), params(0.0, 0.0)).model();
  EXPECT_NEAR(m.base, 0.012, 0.003);
  EXPECT_LT(m.quadratic, 0.0002) << "a time-of-flight σ does not grow with d²";
}

TEST(RangeNoiseEstimate, MeasuresNoiseGrowingWithTheSquareOfTheRange) {
  const RangeNoiseEstimate estimate = estimateOf(noisyScans(0.003, 0.002, 60), params(0.0, 0.0));
  for (std::size_t band : {2u, 4u, 7u}) {
    const double d = band + 0.5;
    EXPECT_NEAR(estimate.bandSigma(band), 0.003 + 0.002 * d * d, 0.25 * (0.003 + 0.002 * d * d)) << band;
  }
  EXPECT_NEAR(estimate.model().quadratic, 0.002, 0.0005);
}

TEST(RangeNoiseEstimate, TheConfiguredModelIsTheFloorOfEachTerm) {
  // Measured: 12 mm flat. Configured: 3 mm + 1 mm/m². The base is raised, the quadratic term stays.
  const RangeNoiseModel m = estimateOf(noisyScans(0.012, 0.0, 60), params(0.003, 0.001)).model();
  EXPECT_NEAR(m.base, 0.012, 0.003);
  EXPECT_DOUBLE_EQ(m.quadratic, 0.001);
  // A quieter sensor than configured changes nothing.
  EXPECT_EQ(estimateOf(noisyScans(0.001, 0.0, 60), params(0.003, 0.001)).model(), (RangeNoiseModel{0.003, 0.001}));
}

TEST(RangeNoiseEstimate, TheConfiguredModelHoldsUntilTwoBandsHaveEnoughSamples) {
  JumpFilterParams p = params(0.003, 0.001);
  p.noise_estimate_min_samples = 1e6;
  EXPECT_EQ(estimateOf(noisyScans(0.03, 0.0, 10), p).model(), (RangeNoiseModel{0.003, 0.001}));
  EXPECT_EQ(RangeNoiseEstimate(params(0.003, 0.001)).model(), (RangeNoiseModel{0.003, 0.001}));
}

TEST(RangeNoiseEstimate, ScatteredReturnsMakeNoBand) {
  // Returns scattered at random (ghosts beyond the walls): no three lie on a surface.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> range(11.0, 12.0);  // the last band, which walls rarely reach
  std::vector<Scan> scans = noisyScans(0.012, 0.0, 60);
  for (Scan& scan : scans)
    for (std::size_t i = 0; i < 200; ++i) scan.ranges[i] = range(rng);
  const RangeNoiseEstimate estimate = estimateOf(scans, params(0.0, 0.0));
  EXPECT_EQ(estimate.bandSigma(11), 0.0);
  EXPECT_NEAR(estimate.model().base, 0.012, 0.003);
  EXPECT_LT(estimate.model().quadratic, 0.0002);
}

TEST(RangeNoiseEstimate, KeepsTheWallsOfANoisierSensorThanConfigured) {
  // 4 cm of noise at every range: the default model's off-surface tolerance
  // (5 cm up to 3 m) cuts wall returns that noise alone pushed off their line.
  const std::vector<Scan> scans = noisyScans(0.04, 0.0, 40);
  const auto wall_points_deleted = [&](bool estimate) {
    JumpFilterParams p = params(0.003, 0.001);
    p.noise_estimate = estimate;
    const auto filter = makeJumpFilter(p, Implementation::kFast);
    std::vector<std::uint8_t> labels;
    long deleted = 0;
    for (const Scan& scan : scans) {
      labels.assign(scan.size(), 0);
      filter->apply(scan, sensor(), labels);
      deleted += std::count(labels.begin(), labels.end(), static_cast<std::uint8_t>(PointCode::kJump));
    }
    return deleted;
  };
  const long fixed = wall_points_deleted(false), measured = wall_points_deleted(true);
  EXPECT_GT(fixed, 100) << "the configured model loses walls here";
  EXPECT_LT(measured, fixed / 4);
}

TEST(RangeNoiseEstimate, AsShippedEachScanIsMeasuredAlone) {
  // The defaults keep no history: the model after a scan depends on that
  // scan only, so a restarted jump_filter labels exactly as before.
  JumpFilterParams shipped;
  shipped.d_max = sensor().range_max;
  const std::vector<Scan> quiet = noisyScans(0.004, 0.0, 30), noisy = noisyScans(0.04, 0.0, 1, 11);
  std::vector<Scan> after_quiet = quiet;
  after_quiet.push_back(noisy.front());
  const RangeNoiseModel alone = estimateOf(noisy, shipped).model();
  EXPECT_EQ(estimateOf(after_quiet, shipped).model(), alone);
  EXPECT_NEAR(alone.base, 0.04, 0.012) << "one 720-beam scan measures it";
}

TEST(RangeNoiseEstimate, BothImplementationsJudgeWithTheSameEstimate) {
  const std::vector<Scan> scans = noisyScans(0.04, 0.0, 20);
  const auto reference = makeJumpFilter(params(0.003, 0.001), Implementation::kReference);
  const auto fast = makeJumpFilter(params(0.003, 0.001), Implementation::kFast);
  std::vector<std::uint8_t> a, b;
  for (const Scan& scan : scans) {
    a.assign(scan.size(), 0), b.assign(scan.size(), 0);
    reference->apply(scan, sensor(), a);
    fast->apply(scan, sensor(), b);
    ASSERT_EQ(a, b);
  }
  EXPECT_EQ(reference->noiseModel(), fast->noiseModel());
  EXPECT_GT(fast->noiseModel().base, 0.03);
}

}  // namespace
}  // namespace scanfilter
