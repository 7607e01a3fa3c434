// The thin-object check (Beyond the paper 25): which returns stand in front
// of both sides, when a cached object lies in a beam's footprint in front of
// its return, and the check inside step 2.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "scan_builder.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/thin_object_check.hpp"

namespace scanfilter {
namespace {

using test::castScan;
using test::kDeg;
using test::World;

constexpr auto kValid = static_cast<std::uint8_t>(PointCode::kValid);
constexpr auto kJump = static_cast<std::uint8_t>(PointCode::kJump);
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kStep = 0.15;  // the depth step of the geometric tests (any value > 0 would do)

Scan scanOf(std::vector<double> ranges) {
  Scan scan;
  scan.angle_increment = 1.0 * kDeg;
  scan.ranges = std::move(ranges);
  return scan;
}

// The beams standing in front in the way asked (by default of both sides).
std::vector<int> flagged(const Scan& scan, std::size_t max_beams, StandsInFront how = StandsInFront::kOfBothSides) {
  const std::vector<StandsInFront> stands = standingInFront(scan, max_beams, kStep);
  std::vector<int> out;
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (stands[i] == how) out.push_back(static_cast<int>(i));
  return out;
}

std::vector<int> besideANoReturn(const Scan& scan, std::size_t max_beams) {
  return flagged(scan, max_beams, StandsInFront::kBesideNoReturn);
}

TEST(InFrontOfBothSides, ShortStretchesWithFartherReturnsOnBothSides) {
  EXPECT_EQ(flagged(scanOf({3, 3, 1, 3, 3}), 2), (std::vector<int>{2}));
  EXPECT_EQ(flagged(scanOf({3, 1.0, 1.1, 3, 3}), 2), (std::vector<int>{1, 2})) << "two returns of one object";
  EXPECT_EQ(flagged(scanOf({3, 1.0, 1.1, 1.0, 3}), 2), (std::vector<int>{})) << "three: longer than max_beams";
  EXPECT_EQ(flagged(scanOf({3, 1.0, 1.1, 1.0, 3}), 3), (std::vector<int>{1, 2, 3}));
}

// A full turn of 360 beams at 3 m: a stretch at the seam has both sides.
TEST(InFrontOfBothSides, AcrossAFullTurnsSeam) {
  std::vector<double> ranges(360, 3.0);
  ranges[359] = 1.0;
  ranges[0] = 1.1;
  EXPECT_EQ(flagged(scanOf(ranges), 2), (std::vector<int>{0, 359}));
  ranges[1] = 1.0;
  EXPECT_EQ(flagged(scanOf(ranges), 2), (std::vector<int>{})) << "three across the seam: longer than max_beams";
  ranges.resize(180);  // half a turn: beams 0 and 179 have one side only
  ranges[1] = 3.0;
  ranges[179] = 1.0;
  EXPECT_EQ(flagged(scanOf(ranges), 2), (std::vector<int>{}));
}

// A leg at 1 m and beside it the mix of the leg and the wall behind at 2 m:
// both stand in front of the wall on either side, the mixed return only
// together with the leg.
TEST(InFrontOfBothSides, AThinObjectWithItsMixedReturnBeside) {
  EXPECT_EQ(flagged(scanOf({3, 3, 1, 2, 3, 3}), 2), (std::vector<int>{2, 3}));
  EXPECT_EQ(flagged(scanOf({3, 3, 1, 2, 3, 3}), 1), (std::vector<int>{2}))
      << "the mixed return alone is beside the leg";
  EXPECT_EQ(flagged(scanOf({3, 3, 1, 2.9, 3, 3}), 2), (std::vector<int>{2}))
      << "the stretch must stand in front as a whole";
}

TEST(InFrontOfBothSides, NotBetweenNotNearNotBesideNothing) {
  EXPECT_EQ(flagged(scanOf({1, 1, 2, 3, 3}), 2), (std::vector<int>{})) << "between an edge and its background";
  EXPECT_EQ(flagged(scanOf({3, 3, 2.9, 3, 3}), 2), (std::vector<int>{})) << "within the depth step: noise";
  EXPECT_EQ(flagged(scanOf({3, 3, 1, kNaN, 3}), 2), (std::vector<int>{}))
      << "nothing within range on one side: no background light to mix there";
  EXPECT_EQ(flagged(scanOf({3, kNaN, 1, 3, 3}), 2), (std::vector<int>{})) << "nor on the other";
  EXPECT_EQ(flagged(scanOf({1, 3, 3, 3, 1}), 2), (std::vector<int>{})) << "at the scan's ends one side is unknown";
  EXPECT_EQ(flagged(scanOf({3, 3, 4, 3, 3}), 2), (std::vector<int>{})) << "behind both sides is no thin object";
}

// Beside a beam without a return the stretch is told apart: its mix needs a
// second object behind it (Beyond the paper 30).
TEST(InFrontOfBothSides, BesideABeamWithoutAReturn) {
  EXPECT_EQ(besideANoReturn(scanOf({3, 3, 1, kNaN, 3}), 2), (std::vector<int>{2}));
  EXPECT_EQ(besideANoReturn(scanOf({3, kNaN, 1, 3, 3}), 2), (std::vector<int>{2}));
  EXPECT_EQ(besideANoReturn(scanOf({3, kNaN, 1, kNaN, 3}), 2), (std::vector<int>{2})) << "on both sides";
  EXPECT_EQ(besideANoReturn(scanOf({3, kNaN, 1, 1.1, 3}), 2), (std::vector<int>{2, 3})) << "two returns of one object";
  EXPECT_EQ(besideANoReturn(scanOf({3, kNaN, 1, 1.1, 1.0, 3}), 2), (std::vector<int>{}))
      << "three: longer than max_beams";
  EXPECT_EQ(besideANoReturn(scanOf({3, 3, 1, 1.05, kNaN, 3}), 2), (std::vector<int>{2, 3}));
  EXPECT_EQ(besideANoReturn(scanOf({kNaN, 3, 3, 1, 1.05}), 2), (std::vector<int>{}))
      << "at a partial scan's end one side is unknown";
  EXPECT_EQ(besideANoReturn(scanOf({3, kNaN, 3, 3, 3}), 2), (std::vector<int>{})) << "a wall going on is no stretch";
  // The leg at 1 m with the mix of it and the wall at 2 m beside it, a beam
  // without a return beyond: the leg stands in front of both sides in the
  // shorter stretch, which wins.
  const Scan leg_and_mix = scanOf({3, 3, 1, 2, kNaN, 3});
  EXPECT_EQ(flagged(leg_and_mix, 2), (std::vector<int>{2}));
  EXPECT_EQ(besideANoReturn(leg_and_mix, 2), (std::vector<int>{3}));
}

TEST(ThinObjectCheck, AnObjectInTheFootprintInFrontOfTheReturn) {
  const ThinObjectCheck check(kStep, 0.02);
  const double step = 1.0 * kDeg;
  const Eigen::Vector2d origin(0, 0), p(3, 0);
  // At 1 m the footprint reaches 0.5 * 1 m * 1° = 8.7 mm off the axis, the
  // object's position 2 cm beyond that.
  const double reach = 0.02 + 0.5 * step;
  ASSERT_DOUBLE_EQ(check.halfWidthAt(1.0, step), reach);
  EXPECT_TRUE(check.inFootprintInFront(origin, p, {1, 0}, step));
  EXPECT_TRUE(check.inFootprintInFront(origin, p, {1, reach - 1e-4}, step));
  EXPECT_FALSE(check.inFootprintInFront(origin, p, {1, reach + 1e-4}, step)) << "beside the footprint";
  EXPECT_TRUE(check.inFootprintInFront(origin, p, {2.8, 0}, step));
  EXPECT_FALSE(check.inFootprintInFront(origin, p, {2.9, 0}, step)) << "within the depth step: p's own object";
  EXPECT_FALSE(check.inFootprintInFront(origin, p, {3.5, 0}, step)) << "behind p";
  EXPECT_FALSE(check.inFootprintInFront(origin, p, {-1, 0}, step)) << "behind the sensor";
  EXPECT_FALSE(check.inFootprintInFront(origin, origin, {1, 0}, step)) << "no beam";
}

TEST(ThinObjectCheck, AnObjectInTheFootprintBehindTheReturn) {
  const ThinObjectCheck check(kStep, 0.02);
  const double step = 1.0 * kDeg;
  const double reach = 6.0;  // the sensor's range
  const Eigen::Vector2d origin(0, 0), p(3, 0);
  const double half_width = check.halfWidthAt(4.0, step);
  EXPECT_TRUE(check.inFootprintBehind(origin, p, {4, 0}, step, reach));
  EXPECT_TRUE(check.inFootprintBehind(origin, p, {4, half_width - 1e-4}, step, reach));
  EXPECT_FALSE(check.inFootprintBehind(origin, p, {4, half_width + 1e-4}, step, reach)) << "beside the footprint";
  EXPECT_TRUE(check.inFootprintBehind(origin, p, {3.2, 0}, step, reach));
  EXPECT_FALSE(check.inFootprintBehind(origin, p, {3.1, 0}, step, reach)) << "within the depth step: p's own object";
  EXPECT_FALSE(check.inFootprintBehind(origin, p, {2, 0}, step, reach)) << "in front of p";
  EXPECT_FALSE(check.inFootprintBehind(origin, p, {6.5, 0}, step, reach)) << "beyond the sensor's range";
  EXPECT_FALSE(check.inFootprintBehind(origin, origin, {1, 0}, step, reach)) << "no beam";
}

// Step 2 on a room with a leg of 1 cm radius about 1 m ahead (one or two beams
// wide at 1°), the sensor moving sideways 5 cm a frame (10 Hz), every return
// valid (step 1 found nothing), so the cache holds the leg as an obstacle
// cell. In the last frame the leg is not seen: the beam towards it reports
// the leg's distance plus `beyond_leg` instead, its neighbours the wall
// behind. Returns that beam's label, after checking that both
// implementations give it.
struct LegScene {
  double beyond_leg = 1.0;  // m
  // In the first this many frames (all 0.25 m+ from the last) one beam ends
  // where the last frame's return will lie, as a rear leg seen from
  // elsewhere would.
  int earlier_there = 0;
  // The first this many of those returns were removed in their own frames
  // (labelled jump there, as other frames' mixed returns of a leg mostly are).
  int earlier_removed = 0;
  // In the last this many frames before the last (all nearer to it than
  // rescue_min_baseline) a kept return lies there too: the same leg's mixes
  // seen from nearly the same place.
  int near_there = 0;
  // This many beams after the one towards the leg report its range too (an
  // object that wide).
  int beside = 0;
  // Not 0: in the last frame thin_object_max_beams beams either side of
  // those report this much more than their range, instead of the wall (a
  // background that near, wide enough that no stretch reaches past it).
  double sides_beyond = 0.0;  // m
  // Not 0: the leg is no solid; the first this many frames each have one
  // return at its centre (before the warm-up, so they all stay valid), the
  // cell's whole count.
  int leg_returns = 0;
  // false: the room has no wall behind the leg (x = 3), so the beams beside
  // the last frame's return reach nothing (Beyond the paper 30).
  bool wall_behind = true;
  // Not 0: a second leg stands this far past the last frame's return, on
  // its beam, in every frame but the last.
  double rear_leg_beyond = 0.0;  // m
  // Not 0: that leg is no solid; the first this many frames each have one
  // return at its centre (before the warm-up, so they all stay valid).
  int rear_leg_returns = 0;
};

std::uint8_t legBeamLabel(const PenetrationFilterParams& p, const LegScene& scene) {
  const SensorInfo sensor = test::simpleSensor();
  World room = World{}.wall({-3, -3}, {3, -3}).wall({-3, 3}, {3, 3}).wall({-3, -3}, {-3, 3});
  if (scene.wall_behind) room.wall({3, -3}, {3, 3});
  World with_leg = room;
  // Inside one 5 cm cell: a leg across a cell corner fills two cells either
  // side of the beam, which step 2's own rule reads as a surface crossed.
  const Eigen::Vector2d leg(1.025, 0.025);
  constexpr double kLegRadius = 0.01;
  with_leg.leg(leg, kLegRadius);
  auto reference = makePenetrationFilter(p, Implementation::kReference);
  auto fast = makePenetrationFilter(p, Implementation::kFast);
  constexpr int kFrames = 16;
  const auto poseOf = [](int k) { return Pose2{0.0, 0.05 * k, 0.0}; };
  const Eigen::Vector2d last_at(0.0, poseOf(kFrames - 1).y);
  const Eigen::Vector2d return_at =
      last_at + (leg - last_at).normalized() * ((leg - last_at).norm() - kLegRadius + scene.beyond_leg);
  const Eigen::Vector2d rear_leg = return_at + (leg - last_at).normalized() * (scene.rear_leg_beyond + kLegRadius);
  if (scene.rear_leg_beyond > 0.0 && scene.rear_leg_returns == 0) with_leg.leg(rear_leg, kLegRadius);
  if (scene.earlier_there > 0) {
    EXPECT_GE(poseOf(kFrames - 1).y - poseOf(scene.earlier_there - 1).y, p.rescue_min_baseline);
  }
  const int near_from = kFrames - 1 - scene.near_there;  // the first near frame
  if (scene.near_there > 0) {
    // Near for the baseline the defaults set (without one, nothing is near).
    EXPECT_LT(poseOf(kFrames - 1).y - poseOf(near_from).y, PenetrationFilterParams{}.rescue_min_baseline);
    EXPECT_GT(near_from, scene.earlier_there) << "near and far frames apart";
  }
  EXPECT_LT(scene.leg_returns, p.min_frames) << "the leg's returns must come before the warm-up ends";
  EXPECT_LT(scene.rear_leg_returns, p.min_frames) << "so must the rear leg's";
  std::uint8_t out = 0;
  for (int k = 0; k < kFrames; ++k) {
    const Pose2 pose = poseOf(k);
    const Eigen::Vector2d sensor_at(pose.x, pose.y);
    const bool last = k == kFrames - 1;
    Scan scan = castScan(last || scene.leg_returns > 0 ? room : with_leg, pose, sensor, 360, 0.1 * k);
    const std::size_t leg_beam = test::beamTowards(scan, sensor, std::atan2(leg.y() - pose.y, leg.x()));
    if (k < scene.leg_returns) scan.ranges[leg_beam] = (leg - sensor_at).norm();
    if (k < scene.rear_leg_returns) {
      const Eigen::Vector2d to = rear_leg - sensor_at;
      scan.ranges[test::beamTowards(scan, sensor, std::atan2(to.y(), to.x()))] = to.norm();
    }
    std::size_t earlier_beam = scan.size();  // none
    if (k < scene.earlier_there || (k >= near_from && !last)) {
      const Eigen::Vector2d to = return_at - sensor_at;
      earlier_beam = test::beamTowards(scan, sensor, std::atan2(to.y(), to.x()));
      scan.ranges[earlier_beam] = to.norm();
    }
    if (last) {
      const double range = (leg - sensor_at).norm() - kLegRadius + scene.beyond_leg;
      for (int b = 0; b <= scene.beside; ++b) scan.ranges[leg_beam + static_cast<std::size_t>(b)] = range;
      const auto side = static_cast<std::size_t>(p.thin_object_max_beams);
      for (std::size_t b = 1; scene.sides_beyond > 0.0 && b <= side; ++b) {
        scan.ranges[leg_beam - b] = range + scene.sides_beyond;
        scan.ranges[leg_beam + static_cast<std::size_t>(scene.beside) + b] = range + scene.sides_beyond;
      }
    }
    std::vector<std::uint8_t> labels(scan.size());
    for (std::size_t i = 0; i < scan.size(); ++i)
      labels[i] = scan.hasReturn(i) ? kValid : static_cast<std::uint8_t>(PointCode::kNoReturn);
    if (k < scene.earlier_removed && earlier_beam < scan.size()) labels[earlier_beam] = kJump;
    std::vector<std::uint8_t> by_reference = labels;
    reference->apply(scan, sensor, by_reference);
    fast->apply(scan, sensor, labels);
    if (!last) continue;
    EXPECT_EQ(by_reference[leg_beam], labels[leg_beam]) << "both implementations run the same check";
    out = labels[leg_beam];
  }
  return out;
}

// The other multi-frame checks off, so that this one alone decides.
PenetrationFilterParams thinObjectsOnly() {
  PenetrationFilterParams p;
  p.free_space_check = false;
  p.surface_memory.lifetime = 0.0;
  return p;
}

TEST(ThinObjectCheck, StepTwoRemovesTheMixedReturnBehindALeg) {
  const PenetrationFilterParams p = thinObjectsOnly();
  ASSERT_TRUE(p.thin_object_check);
  // The last frame sees the leg 1.25 m away and the wall behind it 3.4 m away.
  EXPECT_EQ(legBeamLabel(p, {.beyond_leg = 1.0}), kJump) << "the cached leg lies in its footprint, 1 m in front of it";
  EXPECT_EQ(legBeamLabel(p, {.beyond_leg = 0.2}), kJump) << "20 cm: beyond the depth step";

  EXPECT_EQ(legBeamLabel(p, {.beyond_leg = 0.0}), kValid)
      << "the leg's own return: its cached cell is no object in front of it";
  EXPECT_EQ(legBeamLabel(p, {.beyond_leg = 0.1}), kValid) << "10 cm: within the depth step";

  // Beyond the paper 37: the check's own step, 12 cm (edge_depth_step's
  // 15 cm until then): a mix 14 cm behind the leg is found, not with 15 cm.
  ASSERT_EQ(p.thin_object_depth_step, 0.12);
  EXPECT_EQ(legBeamLabel(p, {.beyond_leg = 0.14}), kJump) << "14 cm: beyond the 12 cm step";
  PenetrationFilterParams wider = p;
  wider.thin_object_depth_step = 0.15;
  EXPECT_EQ(legBeamLabel(wider, {.beyond_leg = 0.14}), kValid) << "14 cm: within a 15 cm step";
  wider.edge_depth_step = 0.05;
  EXPECT_EQ(legBeamLabel(wider, {.beyond_leg = 0.14}), kValid) << "edge_depth_step is not the check's step";
  // The same step for the beams beside it: they must return farther by more.
  EXPECT_EQ(legBeamLabel(p, {.sides_beyond = 0.14}), kJump) << "both sides 14 cm farther: beyond the 12 cm step";
  EXPECT_EQ(legBeamLabel(p, {.sides_beyond = 0.10}), kValid) << "10 cm farther: within it";
  EXPECT_EQ(legBeamLabel(wider, {.sides_beyond = 0.14}), kValid) << "14 cm: within a 15 cm step";

  PenetrationFilterParams off = p;
  off.thin_object_check = false;
  EXPECT_EQ(legBeamLabel(off, {}), kValid) << "the paper's step 2 keeps it";
}

// With no return beside it (nothing within range behind), a return behind a
// cached leg is a mix only of that leg and a second object behind it in the
// footprint, seen in the cache: a chair's front and rear legs. With nothing
// behind it the return is the object's own (Beyond the paper 30).
TEST(ThinObjectCheck, BesideANoReturnAMixNeedsASecondObjectBehind) {
  const PenetrationFilterParams p = thinObjectsOnly();
  ASSERT_TRUE(p.thin_object_beside_no_return);
  EXPECT_EQ(legBeamLabel(p, {.wall_behind = false, .rear_leg_beyond = 0.5}), kJump)
      << "a rear leg 0.5 m behind it in the footprint";
  EXPECT_EQ(legBeamLabel(p, {.wall_behind = false}), kValid) << "nothing behind it within range";
  EXPECT_EQ(legBeamLabel(p, {.wall_behind = false, .rear_leg_beyond = 0.1}), kValid)
      << "10 cm behind it: within the depth step, the return's own object";
  // Behind, an obstacle is needed (more than obs_th cached returns, 2 at 1°).
  // 0.54 m puts the rear leg's returns from the first frames well inside one
  // 5 cm cell (1.5 cm or more from its edges).
  ASSERT_EQ(p.obstacle_threshold, 2);
  EXPECT_EQ(legBeamLabel(p, {.wall_behind = false, .rear_leg_beyond = 0.54, .rear_leg_returns = 3}), kJump)
      << "three cached returns at the rear leg: an obstacle";
  EXPECT_EQ(legBeamLabel(p, {.wall_behind = false, .rear_leg_beyond = 0.54, .rear_leg_returns = 2}), kValid)
      << "two are not";

  PenetrationFilterParams off = p;
  off.thin_object_beside_no_return = false;
  EXPECT_EQ(legBeamLabel(off, {.wall_behind = false, .rear_leg_beyond = 0.5}), kValid)
      << "such stretches not checked";
}

// Returns from elsewhere where the return lies (as many as the rescue needs
// to restore a jump point) say an object stands there: a rear leg partly
// behind a front one is kept.
TEST(ThinObjectCheck, ReturnsFromElsewhereWhereItLiesKeepIt) {
  const PenetrationFilterParams p = thinObjectsOnly();
  ASSERT_EQ(p.rescue_min_count, 5);
  EXPECT_EQ(legBeamLabel(p, {.earlier_there = 5}), kValid) << "five returns from elsewhere vouch for an object there";
  EXPECT_EQ(legBeamLabel(p, {.earlier_there = 4}), kJump) << "four are too few for the rescue, and for this";

  PenetrationFilterParams no_rescue = p;
  no_rescue.rescue_persistent_points = false;
  EXPECT_EQ(legBeamLabel(no_rescue, {.earlier_there = 5}), kJump) << "without the rescue there is no evidence";
}

// Returns from elsewhere that their own frames removed (other frames' mixed
// returns of the same leg) vouch for nothing: the cache must have kept as
// many there (Beyond the paper 31).
TEST(ThinObjectCheck, ReturnsRemovedInTheirOwnFramesDoNotKeepIt) {
  const PenetrationFilterParams p = thinObjectsOnly();
  ASSERT_TRUE(p.thin_object_evidence_kept);
  ASSERT_EQ(p.rescue_min_count, 5);
  EXPECT_EQ(legBeamLabel(p, {.earlier_there = 5, .earlier_removed = 5}), kJump)
      << "five returns from elsewhere, all removed there";
  EXPECT_EQ(legBeamLabel(p, {.earlier_there = 5, .earlier_removed = 1}), kJump)
      << "five returns from elsewhere, four of them kept: fewer than rescue_min_count";
  EXPECT_EQ(legBeamLabel(p, {.earlier_there = 5}), kValid) << "five kept";
  PenetrationFilterParams evidence_alone = p;
  evidence_alone.thin_object_evidence_kept = false;
  EXPECT_EQ(legBeamLabel(evidence_alone, {.earlier_there = 5, .earlier_removed = 5}), kValid)
      << "the rescue's evidence alone counts returns of every label";
}

// The kept returns that spare it count only from frames taken elsewhere
// (the rescue's baseline): from nearly the same place the leg's mixes land
// near this one, and their frames kept them for the same reason (Beyond the
// paper 38). rescue_min_count 3, so that the four near frames would be
// enough without the rule.
TEST(ThinObjectCheck, KeptReturnsFromNearlyTheSamePlaceDoNotKeepIt) {
  PenetrationFilterParams p = thinObjectsOnly();
  ASSERT_TRUE(p.thin_object_kept_from_afar);
  p.rescue_min_count = 3;
  EXPECT_EQ(legBeamLabel(p, {.earlier_there = 3, .earlier_removed = 3, .near_there = 4}), kJump)
      << "three returns from elsewhere, removed there; four kept from nearly here";
  EXPECT_EQ(legBeamLabel(p, {.earlier_there = 3, .near_there = 4}), kValid) << "the three from elsewhere kept";
  PenetrationFilterParams every_frame = p;
  every_frame.thin_object_kept_from_afar = false;
  EXPECT_EQ(legBeamLabel(every_frame, {.earlier_there = 3, .earlier_removed = 3, .near_there = 4}), kValid)
      << "every cached frame's kept returns count (31)";
  PenetrationFilterParams no_baseline = p;
  no_baseline.rescue_min_baseline = 0.0;
  EXPECT_EQ(legBeamLabel(no_baseline, {.earlier_there = 3, .earlier_removed = 3, .near_there = 4}), kValid)
      << "without a baseline every frame is taken from elsewhere";
}

// Something as wide as thin_object_max_beams beams is checked; wider, it is
// no thin object, whatever lies in the footprint of its beams.
TEST(ThinObjectCheck, OnlyStretchesUpToMaxBeams) {
  const PenetrationFilterParams p = thinObjectsOnly();
  ASSERT_EQ(p.thin_object_max_beams, 3);
  EXPECT_EQ(legBeamLabel(p, {.beside = 2}), kJump) << "three beams";
  EXPECT_EQ(legBeamLabel(p, {.beside = 3}), kValid) << "four beams";
}

// Most of a thin leg's returns are mixed and land elsewhere, and the cache
// keeps few on the leg itself: a cell holding thin_object_min_returns (1 at
// 1°) is an object here, though an obstacle needs more than obs_th (Beyond
// the paper 32).
TEST(ThinObjectCheck, ACellHoldingThinObjectMinReturnsIsAnObject) {
  PenetrationFilterParams p = thinObjectsOnly();
  ASSERT_EQ(p.thin_object_min_returns, 1);
  EXPECT_EQ(legBeamLabel(p, {.leg_returns = 1}), kJump) << "one cached return at the leg: an object in the footprint";
  p.thin_object_min_returns = 2;
  EXPECT_EQ(legBeamLabel(p, {.leg_returns = 2}), kJump) << "two, when two are asked for";
  EXPECT_EQ(legBeamLabel(p, {.leg_returns = 1}), kValid) << "one is then not";
}

}  // namespace
}  // namespace scanfilter
