#pragma once
// Scans of a square room with range noise of a known model, for the tests
// of what measures the noise (range_noise_estimate_test, evidence_radius_test).
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "scan_builder.hpp"
#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter::test {

inline constexpr double kNoisyRoomHalfWidth = 6.0;  // m: ranges from 6 to 8.5 m from the middle ...
inline constexpr double kNoisyRoomOffCentre = 4.5;  // m: ... and from 1.5 m up when the sensor stands off centre

inline World noisyRoom() {
  const double h = kNoisyRoomHalfWidth;
  World w;
  w.wall({-h, -h}, {h, -h}).wall({h, -h}, {h, h}).wall({h, h}, {-h, h}).wall({-h, h}, {-h, -h});
  return w;
}

inline SensorInfo noisyRoomSensor() {
  SensorInfo s;
  s.range_min = 0.1;
  s.range_max = 12.0;
  return s;
}

// Scans of the room from a few places, ranges perturbed by σ(d) = base + quadratic·d².
inline std::vector<Scan> noisyRoomScans(double base, double quadratic, int count, std::uint32_t seed = 7) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<Scan> scans;
  for (int k = 0; k < count; ++k) {
    const double x = kNoisyRoomOffCentre * std::cos(0.7 * k), y = kNoisyRoomOffCentre * std::sin(0.7 * k) * 0.5;
    Scan scan = castScan(noisyRoom(), {x, y, 0.1 * k}, noisyRoomSensor(), 720);
    for (double& r : scan.ranges)
      if (std::isfinite(r)) r += (base + quadratic * r * r) * normal(rng);
    scans.push_back(std::move(scan));
  }
  return scans;
}

}  // namespace scanfilter::test
