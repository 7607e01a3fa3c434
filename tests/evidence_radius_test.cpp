// The evidence radius of step 2 (Beyond the paper 33): rescue_radius until
// the range noise is measured, then the larger of it and k σ(range) of the
// measured model alone.
#include <limits>

#include <gtest/gtest.h>

#include "noisy_room.hpp"
#include "scanfilter/evidence_radius.hpp"

namespace scanfilter {
namespace {

constexpr double kFloor = 0.08;  // m, rescue_radius's default
constexpr double kSigmas = 5.0;
constexpr double kCap = 1.0;  // m, above anything measured below but the cap's own test

// Smoothed over many scans, so that the figures below are tight.
EvidenceRadiusParams params(double sigmas = kSigmas, double cap = kCap) {
  return {.min_radius = kFloor, .noise_sigmas = sigmas, .max_radius = cap, .sampling = {200.0, 100.0}};
}

EvidenceRadius measuredOn(const std::vector<Scan>& scans, const EvidenceRadiusParams& p = params(),
                          const SensorInfo& sensor = test::noisyRoomSensor()) {
  EvidenceRadius radius(p);
  for (const Scan& scan : scans) radius.measure(scan, sensor);
  return radius;
}

TEST(EvidenceRadius, RescueRadiusUntilTheNoiseIsMeasured) {
  const EvidenceRadius radius(params());
  EXPECT_DOUBLE_EQ(radius.at(1.0), kFloor);
  EXPECT_DOUBLE_EQ(radius.at(20.0), kFloor);
}

TEST(EvidenceRadius, GrowsWithTheMeasuredNoiseOfANoisySensor) {
  // σ = 6 mm + 2 mm/m²: 5σ is 8 cm at 2.2 m, 39 cm at 6 m.
  const EvidenceRadius radius = measuredOn(test::noisyRoomScans(0.006, 0.002, 60));
  EXPECT_NEAR(radius.noise().quadratic, 0.002, 0.0005);
  EXPECT_DOUBLE_EQ(radius.at(1.0), kFloor) << "near the sensor the noise is within rescue_radius";
  const double sigma_at_6 = 0.006 + 0.002 * 36.0;
  EXPECT_NEAR(radius.at(6.0), kSigmas * sigma_at_6, 0.25 * kSigmas * sigma_at_6);
  EXPECT_GT(radius.at(7.0), radius.at(6.0));
}

TEST(EvidenceRadius, AQuietSensorKeepsRescueRadius) {
  // 3 mm + 1 mm/m², the triangulation default: 5σ reaches 8 cm only at 3.6 m.
  const EvidenceRadius radius = measuredOn(test::noisyRoomScans(0.003, 0.001, 60));
  EXPECT_DOUBLE_EQ(radius.at(3.0), kFloor);
  // A time-of-flight 12 mm at every range: 6 cm, never more than the floor.
  const EvidenceRadius flat = measuredOn(test::noisyRoomScans(0.012, 0.0, 60));
  EXPECT_DOUBLE_EQ(flat.at(10.0), kFloor) << "no configured d² term widens it";
}

TEST(EvidenceRadius, ZeroSigmasMeasuresNothing) {
  const EvidenceRadius radius = measuredOn(test::noisyRoomScans(0.006, 0.002, 60), params(0.0));
  EXPECT_EQ(radius.noise(), (RangeNoiseModel{}));
  EXPECT_DOUBLE_EQ(radius.at(6.0), kFloor);
}

// The sparse-surface search reads the noise (Beyond the paper 42) when the
// rescue's radius does not follow it: measured, and the radius stays put.
TEST(EvidenceRadius, MeasuresTheNoiseForAnotherCheckWithZeroSigmas) {
  EvidenceRadiusParams p = params(0.0);
  p.measure_noise = true;
  const EvidenceRadius radius = measuredOn(test::noisyRoomScans(0.006, 0.002, 60), p);
  EXPECT_NEAR(radius.noise().quadratic, 0.002, 0.0005);
  EXPECT_DOUBLE_EQ(radius.at(6.0), kFloor);
}

TEST(EvidenceRadius, GrowsNoFartherThanTheCap) {
  const EvidenceRadius radius = measuredOn(test::noisyRoomScans(0.006, 0.002, 60), params(kSigmas, 0.3));
  EXPECT_DOUBLE_EQ(radius.at(6.0), 0.3) << "5 sigma is 0.39 m there";
  EXPECT_DOUBLE_EQ(radius.at(100.0), 0.3);
  EXPECT_LT(radius.at(3.0), 0.3);
  const EvidenceRadius below = measuredOn(test::noisyRoomScans(0.006, 0.002, 60), params(kSigmas, 0.05));
  EXPECT_DOUBLE_EQ(below.at(6.0), kFloor) << "a cap below rescue_radius changes nothing";
}

// Without a finite positive range_max there are no bands to measure in:
// rescue_radius, and no fault (a NaN range_max once sized the bands from NaN).
TEST(EvidenceRadius, ASensorWithoutAFiniteRangeKeepsRescueRadius) {
  for (double range_max : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 0.0}) {
    SensorInfo sensor = test::noisyRoomSensor();
    sensor.range_max = range_max;
    const EvidenceRadius radius = measuredOn(test::noisyRoomScans(0.006, 0.002, 10), params(), sensor);
    EXPECT_DOUBLE_EQ(radius.at(6.0), kFloor) << range_max;
  }
}

// A sensor whose range_max changes gets bands for the new range.
TEST(EvidenceRadius, ANewRangeMaxResizesTheBands) {
  EvidenceRadius radius(params());
  SensorInfo short_range = test::noisyRoomSensor();
  short_range.range_max = 2.0;  // one band reached: the estimate cannot fit
  for (const Scan& scan : test::noisyRoomScans(0.006, 0.002, 20)) radius.measure(scan, short_range);
  EXPECT_DOUBLE_EQ(radius.at(6.0), kFloor);
  for (const Scan& scan : test::noisyRoomScans(0.006, 0.002, 60)) radius.measure(scan, test::noisyRoomSensor());
  EXPECT_GT(radius.at(6.0), kFloor);
}

}  // namespace
}  // namespace scanfilter
