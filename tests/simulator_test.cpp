#include <array>

#include <gtest/gtest.h>

#include "scanfilter/artefact_cause.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sim/scan_simulator.hpp"

namespace scanfilter {
namespace {

TEST(Simulator, BuiltInScenesLoad) {
  const auto names = sim::builtinSceneNames();
  EXPECT_GE(names.size(), 3u);
  for (const auto& name : names) {
    const sim::Scene scene = sim::findScene(name);
    EXPECT_FALSE(scene.segments.empty()) << name;
    EXPECT_GE(scene.trajectory.waypoints.size(), 2u) << name;
  }
}

TEST(Simulator, SameSeedSameScans) {
  sim::ScanSimulator a(sim::findScene("hall"), 5), b(sim::findScene("hall"), 5), c(sim::findScene("hall"), 6);
  ScanRecord ra, rb, rc;
  bool differs = false;
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(a.next(ra) && b.next(rb) && c.next(rc));
    for (std::size_t i = 0; i < ra.scan.size(); ++i) {
      EXPECT_TRUE(ra.scan.ranges[i] == rb.scan.ranges[i] || (std::isnan(ra.scan.ranges[i]) && std::isnan(rb.scan.ranges[i])));
      differs |= !(ra.scan.ranges[i] == rc.scan.ranges[i]);
    }
    EXPECT_EQ(ra.scan.truth, rb.scan.truth);
    EXPECT_EQ(ra.scan.truth_cause, rb.scan.truth_cause);
  }
  EXPECT_TRUE(differs) << "another seed gives other noise";
}

TEST(Simulator, ProducesEveryKindOfPoint) {
  sim::ScanSimulator simulator(sim::findScene("office"), 1);
  std::array<std::size_t, kPointCodeCount> counts{};
  std::size_t thin = 0;
  ScanRecord r;
  for (int k = 0; k < 200 && simulator.next(r); ++k) {
    for (std::size_t i = 0; i < r.scan.size(); ++i) {
      ++counts[r.scan.truth[i]];
      EXPECT_EQ(r.scan.truth[i] == static_cast<std::uint8_t>(PointCode::kNoReturn), !r.scan.hasReturn(i));
    }
    thin += r.scan.thin_leg_beams.size();
  }
  for (int c = 0; c < kPointCodeCount; ++c) EXPECT_GT(counts[static_cast<std::size_t>(c)], 0u) << pointCodeName(static_cast<PointCode>(c));
  EXPECT_GT(thin, 0u);
}

// Every artefact says why it is one, and nothing else does; between them
// the hall (a mirroring facade) and the office (a transmitting partition)
// make every cause: both have legs, edges, junctions and grazing walls.
TEST(Simulator, EveryArtefactAndOnlyAnArtefactHasACause) {
  std::array<std::size_t, kArtefactCauseCount> causes{};
  std::size_t without_cause = 0, cause_without_artefact = 0, wrong_step = 0;
  for (const char* name : {"hall", "office"}) {
    sim::ScanSimulator simulator(sim::findScene(name), 1);
    ScanRecord r;
    for (int k = 0; k < 300 && simulator.next(r); ++k) {
      ASSERT_EQ(r.scan.truth_cause.size(), r.scan.size());
      for (std::size_t i = 0; i < r.scan.size(); ++i) {
        const auto cause = static_cast<ArtefactCause>(r.scan.truth_cause[i]);
        ++causes[r.scan.truth_cause[i]];
        const bool artefact = isRemovedCode(r.scan.truth[i]);
        without_cause += artefact && cause == ArtefactCause::kNone;
        cause_without_artefact += !artefact && cause != ArtefactCause::kNone;
        // A misdetection comes from a second path, a jump point from the spot.
        const bool second_path = cause == ArtefactCause::kMirrorGhost || cause == ArtefactCause::kThroughPane;
        wrong_step += artefact && second_path != (r.scan.truth[i] == static_cast<std::uint8_t>(PointCode::kMisdetected));
      }
    }
  }
  EXPECT_EQ(without_cause, 0u);
  EXPECT_EQ(cause_without_artefact, 0u);
  EXPECT_EQ(wrong_step, 0u);
  for (ArtefactCause cause : kEveryArtefactCause)
    EXPECT_GT(causes[static_cast<std::size_t>(cause)], 0u) << artefactCauseName(cause);
}

// Ghosts lie behind the surface the beam hit: farther than the truth range.
TEST(Simulator, MisdetectionsLieBehindTheSmoothWall) {
  sim::ScanSimulator simulator(sim::findScene("hall"), 3);
  const sim::Scene& scene = simulator.scene();
  ScanRecord r;
  std::size_t behind = 0, total = 0;
  while (simulator.next(r)) {
    for (std::size_t i = 0; i < r.scan.size(); ++i) {
      if (r.scan.truth[i] != static_cast<std::uint8_t>(PointCode::kMisdetected)) continue;
      ++total;
      const Eigen::Vector2d p = beamToWorld(r.scan, scene.sensor, i);
      // The hall is 8 x 10 m: a ghost behind a wall is outside, or behind the fridge.
      behind += p.x() < 0 || p.x() > 8 || p.y() < 0 || p.y() > 10 || (p.x() > 7.15 && p.y() > 9.15);
    }
  }
  EXPECT_GT(total, 100u);
  EXPECT_GT(static_cast<double>(behind) / static_cast<double>(total), 0.9);
}

TEST(Simulator, OdometryDriftIsOnUnlessTheSceneTurnsItOff) {
  const std::string plan = "walls:\n  - {points: [[0, 0], [1, 0]]}\ntrajectory: {waypoints: [[0,0.5],[1,1]]}\n";
  const sim::Scene drifting = sim::parseScene(plan, "s.yaml");
  EXPECT_EQ(drifting.odometry.scale_error, sim::kDefaultOdometryDrift.scale_error);
  EXPECT_EQ(drifting.odometry.heading_drift_per_m, sim::kDefaultOdometryDrift.heading_drift_per_m);
  const sim::Scene exact = sim::parseScene(plan + "odometry: {scale_error: 0, heading_drift_deg_per_m: 0}\n", "s.yaml");
  EXPECT_TRUE(exact.odometry.none());
  const sim::Scene more = sim::parseScene(plan + "odometry: {heading_drift_deg_per_m: 2}\n", "s.yaml");
  EXPECT_DOUBLE_EQ(more.odometry.heading_drift_per_m, 2.0 * M_PI / 180.0);
  EXPECT_EQ(more.odometry.scale_error, sim::kDefaultOdometryDrift.scale_error) << "a key left out keeps its default";
}

// The error a scene file gives, as text.
std::string sceneError(const std::string& yaml) {
  try {
    sim::parseScene(yaml, "s.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SimulatorErrors, BadSceneNamesFileLineAndKey) {
  EXPECT_EQ(sceneError("walls:\n  - {points: [[0, 0], [1, 0]], material: velvet}\ntrajectory: {waypoints: [[0,0],[1,1]]}\n"),
            "s.yaml:2: walls[0].material: expected rough, smooth or glass, got \"velvet\"");
  EXPECT_THROW(sim::findScene("no-such-scene"), InputError);
}

TEST(SimulatorErrors, AKeyGivenTwiceInAListedItemNamesTheItem) {
  EXPECT_EQ(sceneError("walls:\n  - {points: [[0, 0], [1, 0]], material: glass, material: rough}\n"),
            "s.yaml:2: walls[0].material: duplicate key (first on line 2); give each key once");
}

// A robot cannot drive through a wall or a leg: scans from there are no
// robot's (the home tour did, docs/simulator.md).
TEST(SimulatorErrors, ATourThroughAWallNamesTheWaypoint) {
  const std::string wall = "walls:\n  - {points: [[1, -1], [1, 1]]}\n";
  EXPECT_EQ(sceneError(wall + "trajectory:\n  waypoints: [[0, 0.5], [0, 0], [2, 0]]\n"),
            "s.yaml:4: trajectory.waypoints[1]: the way from here to waypoints[2] passes 0.000 m from the wall "
            "or box side (1.00, -1.00)-(1.00, 1.00), nearer than trajectory.robot_radius (0.170 m): the robot "
            "would drive through it");
}

TEST(SimulatorErrors, ATourMustKeepTheRobotRadiusFromALeg) {
  // The way passes 0.10 m from the leg's centre, 0.085 m from its surface.
  const std::string scene = "walls:\n  - {points: [[0, 5], [3, 5]]}\nlegs:\n  - {centre: [1.5, 0.1], radius: 0.015}\n";
  const std::string tour = "  waypoints: [[0, 0], [3, 0]]\n";
  EXPECT_THROW(sim::parseScene(scene + "trajectory:\n" + tour, "s.yaml"), InputError);
  EXPECT_THROW(sim::parseScene(scene + "trajectory:\n  robot_radius: 0.09\n" + tour, "s.yaml"), InputError);
  EXPECT_NO_THROW(sim::parseScene(scene + "trajectory:\n  robot_radius: 0.08\n" + tour, "s.yaml"));
}

}  // namespace
}  // namespace scanfilter
