// The accuracy harness: scoring, the comparison's filter families and their
// tuning sweep.
#include <limits>
#include <set>

#include <gtest/gtest.h>

#include "scanfilter/accuracy/comparison_families.hpp"
#include "scanfilter/accuracy/family_tuning.hpp"
#include "scanfilter/accuracy/labelled_logs.hpp"
#include "scanfilter/removal_score.hpp"

namespace scanfilter::accuracy {
namespace {

constexpr auto code(PointCode c) { return static_cast<std::uint8_t>(c); }

TEST(RemovalScore, FalseDeletionsByRangeBandAndClassAgnosticPrecision) {
  Scan scan;
  scan.ranges = {1.0, 3.0, 5.0, 2.0, 2.0, std::numeric_limits<double>::quiet_NaN()};
  scan.truth = {code(PointCode::kValid), code(PointCode::kValid), code(PointCode::kValid),
                code(PointCode::kJump),  code(PointCode::kMisdetected), code(PointCode::kNoReturn)};
  // A baseline that says "jump" for everything it removes.
  const std::vector<std::uint8_t> labels = {code(PointCode::kJump), code(PointCode::kValid), code(PointCode::kJump),
                                            code(PointCode::kJump), code(PointCode::kValid), code(PointCode::kNoReturn)};
  RemovalScore s;
  s.add(scan, labels);
  EXPECT_DOUBLE_EQ(s.falseDeletionRate(0), 1.0);  // the 1 m point
  EXPECT_DOUBLE_EQ(s.falseDeletionRate(1), 0.0);  // the 3 m point
  EXPECT_DOUBLE_EQ(s.falseDeletionRate(2), 1.0);  // the 5 m point
  EXPECT_DOUBLE_EQ(s.falseDeletionRate(), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(s.removalPrecision(s.jump()), 1.0 / 3.0);  // 1 jump point against 2 valid points removed
  EXPECT_DOUBLE_EQ(s.removalPrecision(s.misdetected()), 0.0);
  EXPECT_DOUBLE_EQ(s.artefactRecall(), 0.5);
  EXPECT_DOUBLE_EQ(s.artefactPrecision(), 1.0 / 3.0);
  RemovalScore merged;
  merged.add(s);
  merged.add(s);
  EXPECT_DOUBLE_EQ(merged.falseDeletionRate(2), 1.0);
}

TEST(RemovalScore, RecallByCauseCountsArtefactsOfEachCauseWhateverStepRemovedThem) {
  Scan scan;
  scan.ranges = {1.0, 2.0, 3.0, 4.0};
  scan.truth = {code(PointCode::kMisdetected), code(PointCode::kMisdetected), code(PointCode::kJump),
                code(PointCode::kValid)};
  scan.truth_cause = {static_cast<std::uint8_t>(ArtefactCause::kMirrorGhost),
                      static_cast<std::uint8_t>(ArtefactCause::kMirrorGhost),
                      static_cast<std::uint8_t>(ArtefactCause::kThinObjectMix),
                      static_cast<std::uint8_t>(ArtefactCause::kNone)};
  // One ghost removed as a jump point, the other kept; the mix removed.
  const std::vector<std::uint8_t> labels = {code(PointCode::kJump), code(PointCode::kValid),
                                            code(PointCode::kMisdetected), code(PointCode::kJump)};
  RemovalScore s;
  s.add(scan, labels);
  EXPECT_EQ(s.causeTruth(ArtefactCause::kMirrorGhost), 2u);
  EXPECT_DOUBLE_EQ(s.causeRecall(ArtefactCause::kMirrorGhost), 0.5);
  EXPECT_DOUBLE_EQ(s.causeRecall(ArtefactCause::kThinObjectMix), 1.0);
  EXPECT_EQ(s.causeTruth(ArtefactCause::kThroughPane), 0u);
  EXPECT_EQ(s.causeTruth(ArtefactCause::kNone), 0u) << "the valid point removed is no artefact of any cause";
  RemovalScore merged;
  merged.add(s);
  merged.add(s);
  EXPECT_EQ(merged.causeTruth(ArtefactCause::kMirrorGhost), 4u);
  EXPECT_DOUBLE_EQ(merged.causeRecall(ArtefactCause::kMirrorGhost), 0.5);
}

TEST(SweepPoints, DefaultsFirstThenTheRestOfTheGridWithinTheBudget) {
  for (const auto& family : comparisonFamilies(FilterConfig{})) {
    std::size_t grid = 1;
    for (const auto& axis : family.axes) grid *= axis.values.size();
    const auto all = sweepPoints(family, grid + 10);
    ASSERT_EQ(all.size(), grid) << family.name;
    for (const auto& axis : family.axes) EXPECT_EQ(all.front().at(axis.name), axis.values.front()) << family.name;
    EXPECT_EQ(std::set<ParamValues>(all.begin(), all.end()).size(), grid) << family.name << ": repeated points";
    const auto five = sweepPoints(family, 5);
    ASSERT_EQ(five.size(), std::min<std::size_t>(5, grid));
    EXPECT_EQ(five, sweepPoints(family, 5)) << "deterministic";
    EXPECT_EQ(std::vector<ParamValues>(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(five.size())), five)
        << "a bigger budget extends a smaller one";
  }
}

TEST(SimulateBuiltinScenes, EverySceneAtEverySeedSceneBySceneAsTheVariantAsks) {
  constexpr int kFrames = 3;
  constexpr int kBeams = 90;
  SceneVariant coarse;
  coarse.beams = kBeams;
  const auto logs = simulateBuiltinScenes({7, 8}, kFrames, coarse);
  const auto scenes = sim::builtinSceneNames();
  ASSERT_EQ(logs.size(), 2 * scenes.size());
  for (std::size_t i = 0; i < logs.size(); ++i) {
    EXPECT_EQ(logs[i].name, scenes[i / 2] + " seed " + std::to_string(7 + i % 2));
    ASSERT_EQ(logs[i].scans.size(), static_cast<std::size_t>(kFrames)) << logs[i].name;
    EXPECT_EQ(logs[i].scans.front().size(), static_cast<std::size_t>(kBeams)) << logs[i].name;
  }
}

// Drift is on by default in the simulated logs (the scene's own,
// sim::kDefaultOdometryDrift); a variant replaces it, OdometryDrift{} with the
// true poses. The scans and their truth stay the same.
TEST(SimulateScene, OdometryIsTheScenesUnlessTheVariantReplacesIt) {
  constexpr int kFrames = 20;
  const auto scenes_own = simulateScene("hall", 1, kFrames);
  SceneVariant true_poses, drifting;
  true_poses.odometry = sim::OdometryDrift{};
  drifting.odometry = sim::OdometryDrift{0.05, 0.0};
  const auto truth = simulateScene("hall", 1, kFrames, true_poses);
  const auto odometry = simulateScene("hall", 1, kFrames, drifting);
  EXPECT_EQ(scenes_own.scans.back().pose.x, simulateScene("hall", 1, kFrames).scans.back().pose.x) << "repeatable";
  EXPECT_NE(truth.scans.back().pose.x, scenes_own.scans.back().pose.x) << "the default drifts";
  EXPECT_NE(truth.scans.back().pose.x, odometry.scans.back().pose.x);
  EXPECT_NE(scenes_own.scans.back().pose.x, odometry.scans.back().pose.x);
  EXPECT_EQ(truth.scans.back().truth, odometry.scans.back().truth) << "the same scans, other poses";
  EXPECT_EQ(truth.scans.back().truth, scenes_own.scans.back().truth);
}

TEST(SimulateScene, AnySensorPresetOnAnyScene) {
  SceneVariant tof;
  tof.sensor = "tof";
  const auto log = simulateScene("office", 1, 2, tof);
  EXPECT_EQ(log.name, "office tof seed 1");
  ASSERT_EQ(log.scans.size(), 2u);
  EXPECT_EQ(log.scans.front().size(), 1440u);
  EXPECT_DOUBLE_EQ(log.sensor.range_max, 20.0);
  EXPECT_DOUBLE_EQ(log.sensor.angular_accuracy_deg, 0.25);
  EXPECT_EQ(simulateScene("office", 1, 2).scans.front().size(), 360u) << "without a preset, the scene's own sensor";
}

// bench/sensor_robustness changes a preset's range this way: the scans and
// the header the filter reads both follow.
TEST(SimulateScene, AVariantsAdjustmentComesAfterTheSensorPreset) {
  constexpr double kShorterRange = 3.0;  // m: the office's walls lie farther from much of its tour
  SceneVariant near_only;
  near_only.sensor = "triangulation";
  near_only.adjust = [](sim::Scene& s) { s.sensor.range_max = kShorterRange; };
  SceneVariant preset_alone;
  preset_alone.sensor = "triangulation";
  const auto noReturns = [](const LabelledLog& log) {
    std::size_t count = 0;
    for (const auto& scan : log.scans)
      for (std::size_t i = 0; i < scan.size(); ++i) count += !scan.hasReturn(i);
    return count;
  };
  const auto log = simulateScene("office", 1, 5, near_only);
  const auto preset_log = simulateScene("office", 1, 5, preset_alone);
  EXPECT_DOUBLE_EQ(log.sensor.range_max, kShorterRange);
  EXPECT_DOUBLE_EQ(preset_log.sensor.range_max, 8.0) << "without it, the preset's";
  for (const auto& scan : log.scans) {
    for (std::size_t i = 0; i < scan.size(); ++i) {
      if (!scan.hasReturn(i)) continue;
      EXPECT_LE(scan.ranges[i], kShorterRange) << log.name << " beam " << i;
    }
  }
  EXPECT_GT(noReturns(log), noReturns(preset_log) + log.scans.size() * 10) << "walls beyond 3 m now return nothing";
}

TEST(ScoreFilter, OurConfigScoresAsOurFamilyAtItsDefaults) {
  const std::vector<LabelledLog> logs = {simulateScene("office", 1, 30), simulateScene("home", 1, 30)};
  LogLabels labels;
  const ScoredFilter by_config = scoreFilter(FilterConfig{}, logs, &labels);
  const FilterFamily ours = comparisonFamilies(FilterConfig{}).front();
  const ScoredFilter by_family = scoreFamily(ours, sweepPoints(ours, 1).front(), logs);
  EXPECT_EQ(by_config.scans, 60u);
  EXPECT_EQ(by_config.scans, by_family.scans);
  EXPECT_EQ(by_config.score.jump().truth_removed, by_family.score.jump().truth_removed);
  EXPECT_EQ(by_config.score.misdetected().labelled, by_family.score.misdetected().labelled);
  EXPECT_EQ(by_config.score.validDeleted(), by_family.score.validDeleted());
  EXPECT_GT(by_config.score.jump().truth_removed, 0u) << "the logs have artefacts to find";
  ASSERT_EQ(labels.size(), logs.size());
  for (std::size_t l = 0; l < logs.size(); ++l) {
    ASSERT_EQ(labels[l].size(), logs[l].scans.size());
    EXPECT_EQ(labels[l].back().size(), logs[l].scans.back().size());
  }
}

TEST(TuneFamily, SpendsTheBudgetAndNeverEndsBelowTheDefaults) {
  const std::vector<LabelledLog> logs{simulateScene("office", 1, 40)};
  for (const auto& family : comparisonFamilies(FilterConfig{})) {
    const TunedFamily tuned = tuneFamily(family, logs, 4);
    EXPECT_EQ(tuned.evaluations, 4u) << family.name;
    const double at_default = scoreFamily(family, tuned.defaults, logs).score.artefactF1();
    EXPECT_GE(tuned.tuned_objective, at_default) << family.name;
    EXPECT_DOUBLE_EQ(scoreFamily(family, tuned.tuned, logs).score.artefactF1(), tuned.tuned_objective)
        << family.name << ": scoring is repeatable";
  }
}

}  // namespace
}  // namespace scanfilter::accuracy
