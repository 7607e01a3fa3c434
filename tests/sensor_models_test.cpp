// The simulator's sensor families (config/sensors) and their physics:
// footprint mixing at depth steps, range noise, specular ghosts, glass,
// odometry drift, and truth codes that agree with the geometry.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scanfilter/input_error.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sim/range_mixing.hpp"
#include "scanfilter/sim/scan_simulator.hpp"
#include "scanfilter/sim/sensor_preset.hpp"
#include "scanfilter/sim/specular_return.hpp"
#include "temp_file.hpp"

namespace scanfilter {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr auto kValid = static_cast<std::uint8_t>(PointCode::kValid);
constexpr auto kJump = static_cast<std::uint8_t>(PointCode::kJump);
constexpr auto kMisdetected = static_cast<std::uint8_t>(PointCode::kMisdetected);
constexpr auto kNoReturn = static_cast<std::uint8_t>(PointCode::kNoReturn);

// A scene of bare segments seen by `sensor` (a preset; empty: the default
// model with a 6 m range), the robot driving from `from` to `to` at `speed`,
// logging its true poses.
sim::Scene bareScene(std::vector<sim::Segment> segments, Eigen::Vector2d from, Eigen::Vector2d to, double speed,
                     const std::string& sensor) {
  sim::Scene scene;
  scene.name = "test";
  scene.sensor.range_min = 0.15;
  scene.sensor.range_max = 6.0;
  scene.segments = std::move(segments);
  scene.trajectory.waypoints = {from, to};
  scene.trajectory.speed = speed;
  if (!sensor.empty()) sim::applySensor(scene, sensor);
  scene.odometry = {};
  return scene;
}

// A depth step: a foreground wall x = 2 for y >= 0 in front of a background
// wall x = 5; the robot at (0, -1) faces +y, so the step lies at a bearing of
// atan2(1, 2) and the beams just below it straddle the edge.
constexpr double kForegroundX = 2.0;
constexpr double kBackgroundX = 5.0;
sim::Scene depthStep(const std::string& sensor) {
  using sim::Material;
  return bareScene({{{kForegroundX, 0.0}, {kForegroundX, 5.0}, Material::kRough},
                    {{kBackgroundX, -5.0}, {kBackgroundX, 5.0}, Material::kRough}},
                   {0.0, -1.0}, {0.0, -0.6}, 0.1, sensor);
}

double sigmaOf(const sim::LidarModel& m, double d) { return m.noise_sigma_base + m.noise_sigma_quadratic * d * d; }

TEST(RangeMixing, LinearIsTheWeightedMeanAndInverseDepthTheWeightedHarmonicMean) {
  const std::vector<sim::PartialReturn> parts = {{2.0, 0.7}, {5.0, 0.3}};
  EXPECT_DOUBLE_EQ(sim::mixRanges(sim::RangeMixing::kLinear, parts), 0.7 * 2.0 + 0.3 * 5.0);
  EXPECT_DOUBLE_EQ(sim::mixRanges(sim::RangeMixing::kInverseDepth, parts), 1.0 / (0.7 / 2.0 + 0.3 / 5.0));
  EXPECT_DOUBLE_EQ(sim::mixRanges(sim::RangeMixing::kLinear, {{3.0, 0.2}, {4.0, 0.0}}), 3.0) << "no light, no say";
  EXPECT_TRUE(std::isnan(sim::mixRanges(sim::RangeMixing::kInverseDepth, {})));
}

TEST(SpecularReturn, SeenHeadOnRarelyObliquelyAndGlassReflectsAsFresnelSays) {
  const sim::SpecularSurface smooth{10.0, 0.1};
  EXPECT_DOUBLE_EQ(sim::directReturnProbability(smooth, 0.0), 1.0);
  EXPECT_NEAR(sim::directReturnProbability(smooth, 40 * kDeg), 0.1, 1e-3) << "outside the lobe: the diffuse part";
  EXPECT_GT(sim::directReturnProbability(smooth, 5 * kDeg), 0.8);
  // Float glass, n = 1.5: 4 % a face at normal incidence, (0.04 + 0.04) / 1.04 a pane.
  EXPECT_NEAR(sim::paneReflectance(0.0, 1.5), 2 * 0.04 / 1.04, 1e-9);
  EXPECT_LT(sim::paneReflectance(45 * kDeg, 1.5), 0.12);
  EXPECT_GT(sim::paneReflectance(85 * kDeg, 1.5), 0.5) << "grazing: most light is reflected";
}

TEST(SensorPresets, BothFamiliesLoadWithTheirNumbersAndKeepTheRobotsMount) {
  const auto names = sim::builtinSensorNames();
  ASSERT_NE(std::find(names.begin(), names.end(), "tof"), names.end());
  ASSERT_NE(std::find(names.begin(), names.end(), "triangulation"), names.end());
  const sim::Scene hall = sim::findScene("hall");
  const sim::Scene tof = sim::sceneWithSensor("hall", "tof");
  EXPECT_EQ(tof.lidar.mixing, sim::RangeMixing::kLinear);
  EXPECT_EQ(tof.lidar.beams, 1440);
  EXPECT_DOUBLE_EQ(tof.sensor.angular_accuracy_deg, 0.25);
  EXPECT_DOUBLE_EQ(tof.sensor.range_max, 20.0);
  EXPECT_DOUBLE_EQ(tof.lidar.noise_sigma_quadratic, 0.0);
  EXPECT_DOUBLE_EQ(tof.sensor.mount.x, hall.sensor.mount.x);
  EXPECT_EQ(tof.sensor.direction, hall.sensor.direction);
  EXPECT_EQ(tof.sensor_preset, "tof");
  const sim::Scene tri = sim::sceneWithSensor("office", "triangulation", 720);
  EXPECT_EQ(tri.lidar.mixing, sim::RangeMixing::kInverseDepth);
  EXPECT_GT(tri.lidar.noise_sigma_quadratic, 0.0);
  EXPECT_EQ(tri.lidar.beams, 720);
  EXPECT_DOUBLE_EQ(tri.sensor.angular_accuracy_deg, 0.5) << "Δθ follows the step";
  EXPECT_THROW(sim::sceneWithSensor("hall", "sonar"), InputError);
}

// The fraction of the footprint on the foreground is known from the geometry
// when the spot is an angular fan from the sensor (no aperture, no sweep): the
// reported range must follow each family's mixing formula.
TEST(FootprintMixing, ToFMixesRangesLinearlyAndTriangulationMixesInverseDepth) {
  for (const auto mixing : {sim::RangeMixing::kLinear, sim::RangeMixing::kInverseDepth}) {
    sim::Scene scene = depthStep("tof");
    scene.lidar.mixing = mixing;
    scene.lidar.noise_sigma_base = 0.0;
    scene.lidar.range_resolution = 1e-6;
    scene.lidar.dropout_probability = 0.0;
    scene.lidar.exit_aperture = 0.0;
    scene.lidar.footprint_rays = 4000;
    sim::ScanSimulator simulator(scene, 1);
    ScanRecord r;
    ASSERT_TRUE(simulator.next(r));
    const double divergence = scene.lidar.beam_divergence_mrad * 1e-3;
    const Eigen::Vector2d origin = sensorOrigin(r.scan.pose, scene.sensor.mount);
    const double edge = std::atan2(0.0 - origin.y(), kForegroundX - origin.x());
    std::size_t checked = 0;
    for (std::size_t i = 0; i < r.scan.size(); ++i) {
      const double phi = beamWorldAngle(r.scan, scene.sensor, i);
      const double past_edge = std::remainder(phi - edge, 2 * std::numbers::pi);
      const double f = std::clamp((past_edge + divergence / 2) / divergence, 0.0, 1.0);  // on the foreground
      if (f < 0.05 || f > 0.95 || std::cos(phi) < 0.5) continue;
      const double fg = (kForegroundX - origin.x()) / std::cos(phi), bg = (kBackgroundX - origin.x()) / std::cos(phi);
      const double expected = mixing == sim::RangeMixing::kLinear ? f * fg + (1 - f) * bg : 1.0 / (f / fg + (1 - f) / bg);
      // Tolerance: ranges vary across the 15 mrad fan (about 1 %), fractions sample to 1/4000.
      EXPECT_NEAR(r.scan.ranges[i], expected, 0.01 * bg) << "beam " << i << " f " << f;
      EXPECT_EQ(r.scan.truth[i], kJump) << "off both walls by far more than the noise";
      ++checked;
    }
    EXPECT_GE(checked, 2u) << "the 15 mrad spot straddles the edge over several 0.25° steps";
  }
}

// At 0.25°, 0.5° and 1° the footprint straddles the edge in some beam of
// every scan: mixed returns (jump points) appear at every resolution, each
// between the foreground and the background.
TEST(FootprintMixing, MixedReturnsAtEdgesAtEveryAngularStep) {
  struct Case {
    const char* sensor;
    int beams;
  };
  for (const Case c : {Case{"tof", 1440}, Case{"tof", 720}, Case{"tof", 360}, Case{"triangulation", 360}}) {
    sim::Scene scene = depthStep(c.sensor);
    sim::setBeams(scene, c.beams);
    sim::ScanSimulator simulator(scene, 2);
    ScanRecord r;
    std::size_t mixed = 0, frames = 0;
    while (simulator.next(r)) {
      ++frames;
      const Eigen::Vector2d origin = sensorOrigin(r.scan.pose, scene.sensor.mount);
      for (std::size_t i = 0; i < r.scan.size(); ++i) {
        if (r.scan.truth[i] != kJump) continue;
        const double phi = beamWorldAngle(r.scan, scene.sensor, i);
        const double fg = (kForegroundX - origin.x()) / std::cos(phi), bg = (kBackgroundX - origin.x()) / std::cos(phi);
        const double tolerance = 5 * sigmaOf(scene.lidar, bg);
        EXPECT_GT(r.scan.ranges[i], fg - tolerance) << c.sensor << " " << c.beams;
        EXPECT_LT(r.scan.ranges[i], bg + tolerance) << c.sensor << " " << c.beams;
        ++mixed;
      }
    }
    EXPECT_GT(frames, 0u);
    EXPECT_GE(mixed, frames) << c.sensor << " at " << c.beams << " beams: at least one mixed return a scan";
  }
}

// The sample standard deviation of ranges off a rough wall seen head-on
// matches σ(d) = base + quadratic·d² of each family within 10 % (the
// standard error of a standard deviation over these samples is 2-4 %).
TEST(RangeNoise, SigmaGrowsWithTheSquareOfTheRangeForTriangulationOnlyWithinTolerance) {
  struct Case {
    const char* sensor;
    double distance;
  };
  for (const Case c : {Case{"tof", 2.0}, Case{"tof", 10.0}, Case{"triangulation", 2.0}, Case{"triangulation", 6.0}}) {
    const double d = c.distance;
    sim::Scene scene = bareScene({{{-20.0, d}, {20.0, d}, sim::Material::kRough}}, {0.0, 0.0}, {0.3, 0.0}, 0.005,
                                 c.sensor);
    sim::ScanSimulator simulator(scene, 3);
    ScanRecord r;
    double sum = 0, sum2 = 0;
    std::size_t n = 0;
    while (simulator.next(r)) {
      const Eigen::Vector2d origin = sensorOrigin(r.scan.pose, scene.sensor.mount);
      for (std::size_t i = 0; i < r.scan.size(); ++i) {
        const double phi = beamWorldAngle(r.scan, scene.sensor, i);
        if (std::abs(phi - 90 * kDeg) > 3 * kDeg || !r.scan.hasReturn(i)) continue;
        const double residual = r.scan.ranges[i] - (d - origin.y()) / std::sin(phi);
        sum += residual, sum2 += residual * residual, ++n;
      }
    }
    ASSERT_GT(n, 500u) << c.sensor;
    const double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
    const double expected = sigmaOf(scene.lidar, d);
    EXPECT_NEAR(sigma, expected, 0.1 * expected) << c.sensor << " at " << d << " m, " << n << " samples";
    EXPECT_LT(std::abs(mean), 0.2 * expected) << c.sensor << ": head-on, the footprint adds no bias";
  }
}

// A room with a smooth (mirror) wall at y = 2: beams that hit it off its
// specular lobe are mirrored back into the room and return ghosts behind it.
// That happens per beam, so at any angular step.
TEST(SpecularGhosts, AppearBehindAMirrorWallAt360And1080And3600Beams) {
  using sim::Material;
  for (const int beams : {360, 1080, 3600}) {
    sim::Scene scene = bareScene({{{-3, -2}, {3, -2}, Material::kRough},
                                  {{3, -2}, {3, 2}, Material::kRough},
                                  {{3, 2}, {-3, 2}, Material::kSmooth},
                                  {{-3, 2}, {-3, -2}, Material::kRough}},
                                 {-1.0, 0.5}, {1.0, 0.5}, 0.4, "");
    sim::setBeams(scene, beams);
    sim::ScanSimulator simulator(scene, 4);
    ScanRecord r;
    std::size_t ghosts = 0, behind = 0, mirror_hits = 0, mirror_seen = 0;
    const sim::RayCaster caster(scene);
    while (simulator.next(r)) {
      const Eigen::Vector2d origin = sensorOrigin(r.scan.pose, scene.sensor.mount);
      for (std::size_t i = 0; i < r.scan.size(); ++i) {
        const double phi = beamWorldAngle(r.scan, scene.sensor, i);
        const Eigen::Vector2d dir(std::cos(phi), std::sin(phi));
        const auto hit = caster.cast(origin, dir, scene.sensor.range_max);
        // Off the lobe (more than 3 lobe widths from the normal) the wall is rarely seen itself.
        if (hit && hit->material == Material::kSmooth && std::abs(dir.dot(hit->normal)) < std::cos(30 * kDeg)) {
          ++mirror_hits;
          mirror_seen += r.scan.truth[i] == kValid;
        }
        if (r.scan.truth[i] != kMisdetected) continue;
        ++ghosts;
        behind += beamToWorld(r.scan, scene.sensor, i).y() > 2.0;
      }
    }
    EXPECT_GT(ghosts, static_cast<std::size_t>(beams) / 10) << beams << " beams";
    EXPECT_EQ(behind, ghosts) << beams << " beams: every ghost lies behind the mirror";
    ASSERT_GT(mirror_hits, 0u);
    EXPECT_LT(static_cast<double>(mirror_seen) / static_cast<double>(mirror_hits), 0.2) << beams << " beams";
  }
}

// Glass transmits most light: beams through a pane return the wall behind
// it (misdetected), some reflect (ghosts on the sensor's side of the pane
// mirrored behind it), and head-on the pane itself is seen.
TEST(Glass, MostBeamsPassThroughAndThePaneIsSeenHeadOn) {
  using sim::Material;
  sim::Scene scene = bareScene({{{-10, 1.5}, {10, 1.5}, Material::kGlass}, {{-10, 3.0}, {10, 3.0}, Material::kRough},
                                {{-10, -3.0}, {10, -3.0}, Material::kRough}},
                               {-0.5, 0.0}, {0.5, 0.0}, 0.2, "");
  sim::ScanSimulator simulator(scene, 5);
  ScanRecord r;
  std::size_t pane = 0, through = 0, head_on = 0, head_on_seen = 0;
  while (simulator.next(r)) {
    const Eigen::Vector2d origin = sensorOrigin(r.scan.pose, scene.sensor.mount);
    for (std::size_t i = 0; i < r.scan.size(); ++i) {
      const double phi = beamWorldAngle(r.scan, scene.sensor, i);
      if (std::sin(phi) < 0.5) continue;  // beams towards the pane, under 60° of incidence
      ++pane;
      const double to_wall = (3.0 - origin.y()) / std::sin(phi);
      through += r.scan.truth[i] == kMisdetected && std::abs(r.scan.ranges[i] - to_wall) < 0.1;
      if (std::abs(phi - 90 * kDeg) < 1.5 * kDeg) {
        ++head_on;
        head_on_seen += r.scan.truth[i] == kValid;
      }
    }
  }
  EXPECT_GT(static_cast<double>(through) / static_cast<double>(pane), 0.6);
  EXPECT_GT(static_cast<double>(head_on_seen) / static_cast<double>(head_on), 0.8);
}

TEST(OdometryDriftInLogs, OnByDefaultOffWhenAskedAndTheTruthFromTheTruePoses) {
  constexpr int kFrames = 51;  // 50 steps of 4 cm along the hall's first, straight leg
  sim::Scene drifting = sim::findScene("hall");
  ASSERT_FALSE(drifting.odometry.none()) << "drift is on by default";
  sim::Scene exact = drifting;
  exact.odometry = {};
  sim::ScanSimulator a(drifting, 6), b(exact, 6);
  ScanRecord ra, rb;
  for (int k = 0; k < kFrames; ++k) {
    ASSERT_TRUE(a.next(ra) && b.next(rb));
    EXPECT_EQ(ra.scan.truth, rb.scan.truth) << "the truth comes from the true poses";
    for (std::size_t i = 0; i < ra.scan.size(); ++i)
      ASSERT_TRUE(ra.scan.ranges[i] == rb.scan.ranges[i] || (std::isnan(ra.scan.ranges[i]) && std::isnan(rb.scan.ranges[i])));
  }
  EXPECT_EQ(rb.scan.pose.x, b.truePose().x) << "off: the true poses exactly";
  EXPECT_EQ(rb.scan.pose.theta, b.truePose().theta);
  const double travelled = std::hypot(a.truePose().x - 1.2, a.truePose().y - 1.2);
  ASSERT_NEAR(travelled, 2.0, 0.05);
  const sim::OdometryDrift& d = sim::kDefaultOdometryDrift;
  EXPECT_NEAR(ra.scan.pose.theta - a.truePose().theta, d.heading_drift_per_m * travelled, 1e-9);
  EXPECT_NEAR(std::hypot(ra.scan.pose.x - 1.2, ra.scan.pose.y - 1.2), (1 + d.scale_error) * travelled, 1e-3);
}

// Whatever the sensor: no return exactly where there is no range; valid
// returns on a surface within the noise; misdetected returns farther than
// the first surface along the beam.
TEST(TruthCodes, AgreeWithTheGeometryForEverySensorAndScene) {
  for (const std::string sensor : {"", "tof", "triangulation"}) {
    for (const auto& name : sim::builtinSceneNames()) {
      sim::Scene scene = sim::sceneWithSensor(name, sensor);
      scene.odometry = {};
      if (sensor.empty()) scene.lidar.grazing_probability = scene.lidar.junction_probability = 0.0;
      const sim::RayCaster caster(scene);
      sim::ScanSimulator simulator(scene, 7);
      ScanRecord r;
      std::array<std::size_t, kPointCodeCount> counts{};
      for (int k = 0; k < 30 && simulator.next(r); ++k) {
        const Eigen::Vector2d origin = sensorOrigin(r.scan.pose, scene.sensor.mount);
        for (std::size_t i = 0; i < r.scan.size(); ++i) {
          const std::uint8_t t = r.scan.truth[i];
          ++counts[t];
          ASSERT_EQ(t == kNoReturn, !r.scan.hasReturn(i)) << name << " " << sensor;
          if (t == kNoReturn) continue;
          const double range = r.scan.ranges[i];
          const double sigma = sigmaOf(scene.lidar, range);
          const Eigen::Vector2d p = beamToWorld(r.scan, scene.sensor, i);
          if (t == kValid) {
            EXPECT_LT(caster.distanceToSurface(p), std::max(scene.lidar.jump_min_error, 4 * sigma) + 5 * sigma)
                << name << " " << sensor << " beam " << i;
          } else if (t == kMisdetected) {
            const double phi = beamWorldAngle(r.scan, scene.sensor, i);
            const auto first = caster.cast(origin, {std::cos(phi), std::sin(phi)}, scene.sensor.range_max);
            ASSERT_TRUE(first.has_value());
            EXPECT_GT(range, first->range + scene.lidar.jump_min_error - 5 * sigma) << name << " " << sensor;
          }
        }
      }
      EXPECT_GT(counts[kValid], 0u);
      EXPECT_GT(counts[kJump], 0u) << name << " " << sensor;
    }
  }
}

TEST(SensorPresetErrors, NameTheFileLineAndKey) {
  sim::Scene scene = sim::findScene("hall");
  const test::TempFile mounted("mounted-sensor.yaml", "sensor:\n  range_max: 8\n  mount: [0, 0, 0]\n");
  try {
    sim::applySensor(scene, mounted.path());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), mounted.path() + ":3: sensor.mount: unknown key") << "the mount is the robot's";
  }
  const test::TempFile mixing("mixing-sensor.yaml", "sensor:\n  range_max: 8\nlidar:\n  mixing: average\n");
  try {
    sim::applySensor(scene, mixing.path());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              mixing.path() + ":4: lidar.mixing: expected linear or inverse_depth, got \"average\"");
  }
}

}  // namespace
}  // namespace scanfilter
