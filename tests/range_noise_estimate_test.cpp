// The range-noise estimate of step 1 (Beyond the paper 18): σ(d) measured on
// scans of a known noise, the configured model as the floor, the bands that
// do not count, and what it changes in the jump filter.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "noisy_room.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/range_noise_estimate.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {
namespace {

SensorInfo sensor() { return test::noisyRoomSensor(); }

std::vector<Scan> noisyScans(double base, double quadratic, int count, std::uint32_t seed = 7) {
  return test::noisyRoomScans(base, quadratic, count, seed);
}

// Smoothed over many scans, so that the figures below are tight.
JumpFilterParams params(double base, double quadratic) {
  JumpFilterParams p;
  p.noise_sigma_base = base;
  p.noise_sigma_quadratic = quadratic;
  p.d_max = sensor().range_max;
  p.noise_sampling.window_scans = 200;
  p.noise_sampling.min_samples = 100;
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
  p.noise_sampling.min_samples = 1e6;
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
