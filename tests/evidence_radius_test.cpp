// The evidence radius of step 2 (Beyond the paper 33): rescue_radius until
// the range noise is measured, then the larger of it and k σ(range) of the
// measured model alone.
#include <gtest/gtest.h>

#include "noisy_room.hpp"
#include "scanfilter/evidence_radius.hpp"

namespace scanfilter {
namespace {

constexpr double kFloor = 0.08;  // m, rescue_radius's default
constexpr double kSigmas = 5.0;

// Smoothed over many scans, so that the figures below are tight.
RangeNoiseSampling smoothed() { return {200.0, 100.0}; }

EvidenceRadius measuredOn(const std::vector<Scan>& scans, double sigmas = kSigmas) {
  EvidenceRadius radius(kFloor, sigmas, smoothed());
  for (const Scan& scan : scans) radius.measure(scan, test::noisyRoomSensor());
  return radius;
}

TEST(EvidenceRadius, RescueRadiusUntilTheNoiseIsMeasured) {
  const EvidenceRadius radius(kFloor, kSigmas, smoothed());
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
  const EvidenceRadius radius = measuredOn(test::noisyRoomScans(0.006, 0.002, 60), 0.0);
  EXPECT_EQ(radius.noise(), (RangeNoiseModel{}));
  EXPECT_DOUBLE_EQ(radius.at(6.0), kFloor);
}

}  // namespace
}  // namespace scanfilter
