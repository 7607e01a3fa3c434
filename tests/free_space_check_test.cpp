// The free-space check (Beyond the paper 17): range images looked up by
// bearing, one frame's sighting of a point, and the check inside step 2.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "scan_builder.hpp"
#include "scanfilter/free_space_check.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/range_image.hpp"

namespace scanfilter {
namespace {

using test::castScan;
using test::kDeg;
using test::World;

constexpr auto kValid = static_cast<std::uint8_t>(PointCode::kValid);
constexpr auto kJump = static_cast<std::uint8_t>(PointCode::kJump);
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A full turn of 360 beams, every range `range`, from the origin.
Scan flatScan(double range) {
  Scan scan;
  scan.angle_min = 0.0;
  scan.angle_increment = 1.0 * kDeg;
  scan.ranges.assign(360, range);
  return scan;
}

// Every return kept, as the filter labels a frame it leaves alone.
std::vector<std::uint8_t> allKept(const Scan& scan) {
  std::vector<std::uint8_t> labels(scan.size(), kValid);
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (!scan.hasReturn(i)) labels[i] = static_cast<std::uint8_t>(PointCode::kNoReturn);
  return labels;
}

RangeImage imageOf(const Scan& scan, const Eigen::Isometry2d& correction = Eigen::Isometry2d::Identity()) {
  return RangeImage(scan, test::simpleSensor(), correction, allKept(scan));
}

Eigen::Vector2d atBearing(double degrees, double distance) {
  return distance * Eigen::Vector2d(std::cos(degrees * kDeg), std::sin(degrees * kDeg));
}

TEST(RangeImage, BracketsAPointByItsWorldBearing) {
  Scan scan = flatScan(3.0);
  scan.ranges[10] = 1.0;
  scan.ranges[11] = 2.0;
  const RangeImage image = imageOf(scan);
  const auto b = image.bracket(atBearing(10.5, 1.5));
  ASSERT_TRUE(b);
  EXPECT_FLOAT_EQ(b->first, 1.0f);
  EXPECT_FLOAT_EQ(b->second, 2.0f);
  EXPECT_FLOAT_EQ(b->before, 3.0f);
  EXPECT_DOUBLE_EQ(b->distance, 1.5);
  // Turned 5° by the alignment's correction, beams 10-11 look at 15-16°.
  Eigen::Isometry2d turned = Eigen::Isometry2d::Identity();
  turned.rotate(5.0 * kDeg);
  const RangeImage rotated = imageOf(scan, turned);
  EXPECT_FLOAT_EQ(rotated.bracket(atBearing(15.5, 1.5))->first, 1.0f);
  // Across the seam of a full turn: beams 359 and 0.
  scan.ranges[359] = 0.5;
  const RangeImage seam = imageOf(scan);
  const auto s = seam.bracket(atBearing(-0.5, 1.0));
  ASSERT_TRUE(s);
  EXPECT_FLOAT_EQ(s->first, 0.5f);
  EXPECT_FLOAT_EQ(s->second, 3.0f);
}

TEST(RangeImage, NothingOutsideAPartialTurn) {
  Scan scan = flatScan(3.0);
  scan.ranges.resize(180);  // 0-179°
  const RangeImage image = imageOf(scan);
  EXPECT_TRUE(image.bracket(atBearing(90.0, 1.0)));
  EXPECT_FALSE(image.bracket(atBearing(-90.0, 1.0)));
  EXPECT_FALSE(image.bracket(atBearing(179.5, 1.0))) << "beam 179 has no right-hand partner";
  EXPECT_FALSE(image.bracket(Eigen::Vector2d::Zero())) << "at the sensor there is no bearing";
}

// A 240° clockwise scanner (a URG), beam 0 at +120°: its far end lies more
// than 180° from beam 0.
TEST(RangeImage, APartialTurnWiderThanAHalfTurnClockwise) {
  Scan scan = flatScan(3.0);
  scan.ranges.resize(240);
  scan.angle_min = -120.0 * kDeg;  // clockwise: beam i looks at 120° - i
  scan.ranges[220] = 1.0;  // at 120 - 220 = -100°
  SensorInfo sensor = test::simpleSensor();
  sensor.direction = BeamDirection::kCw;
  const RangeImage image(scan, sensor, Eigen::Isometry2d::Identity(), allKept(scan));
  const auto b = image.bracket(atBearing(-99.5, 0.5));  // between beams 219 and 220
  ASSERT_TRUE(b);
  EXPECT_FLOAT_EQ(b->second, 1.0f);
  EXPECT_FALSE(image.bracket(atBearing(150.0, 0.5))) << "behind the scanner";
}

TEST(RangeImage, ReturnsTheFilterRemovedAreNoReturn) {
  Scan scan = flatScan(3.0);
  std::vector<std::uint8_t> labels = allKept(scan);
  labels[10] = static_cast<std::uint8_t>(PointCode::kMisdetected);  // a ghost through a pane
  const RangeImage image(scan, test::simpleSensor(), Eigen::Isometry2d::Identity(), labels);
  EXPECT_TRUE(std::isnan(image.bracket(atBearing(10.5, 1.0))->first));
}

TEST(FreeSpaceCheck, ASightingIsThroughHitOrNothing) {
  const FreeSpaceCheck check(PenetrationFilterParams{});
  const Eigen::Vector2d p = atBearing(10.5, 1.0);
  const auto sightingWith = [&](double first, double second, double outer = 3.0) {
    Scan scan = flatScan(outer);
    scan.ranges[10] = first;
    scan.ranges[11] = second;
    return check.sighting(imageOf(scan), p);
  };
  using S = FreeSpaceCheck::Sighting;
  EXPECT_EQ(sightingWith(3.0, 3.0), S::kThrough) << "both beams went on to the wall behind";
  EXPECT_EQ(sightingWith(1.05, 3.0), S::kHit) << "one beam ended at the point";
  EXPECT_EQ(sightingWith(2.0, 3.0), S::kNone) << "a dip: something stood partly in the beam";
  EXPECT_EQ(sightingWith(3.0, 2.96), S::kThrough) << "a slanted background is no dip";
  EXPECT_EQ(sightingWith(3.0, 3.0, 1.05), S::kNone)
      << "the outer beams end at the point: a beam of pose error";
  EXPECT_EQ(sightingWith(0.5, 3.0), S::kNone) << "ended short of the point: it says nothing";
  EXPECT_EQ(sightingWith(kNaN, 3.0), S::kNone) << "no return: unknown, not free";
}

// The margin grows with the point's distance from the frame's sensor: a
// beam that went on 12 cm beyond a point 1 m away passed through it, the
// same 12 cm beyond a point 4 m away is within what noise and a leftover
// pose rotation can do there (0.10 m + 0.01 m per m: 14 cm).
TEST(FreeSpaceCheck, TheMarginGrowsWithDistance) {
  PenetrationFilterParams params;
  ASSERT_DOUBLE_EQ(params.free_space_margin, 0.10);
  ASSERT_DOUBLE_EQ(params.free_space_margin_per_m, 0.01);
  const FreeSpaceCheck check(params);
  const auto sightingAt = [&](double distance) {
    const Scan scan = flatScan(distance + 0.12);
    return check.sighting(imageOf(scan), atBearing(10.5, distance));
  };
  using S = FreeSpaceCheck::Sighting;
  EXPECT_EQ(sightingAt(1.0), S::kThrough);
  EXPECT_EQ(sightingAt(4.0), S::kHit) << "12 cm is within the 14 cm margin at 4 m";
  params.free_space_margin_per_m = 0.0;
  EXPECT_EQ(FreeSpaceCheck(params).sighting(imageOf(flatScan(4.12)), atBearing(10.5, 4.0)), S::kThrough)
      << "without the growth, 12 cm beyond is through at any distance";
}

TEST(FreeSpaceCheck, AtLeastMinFramesAndMoreThanHit) {
  PenetrationFilterParams p;
  p.free_space_min_frames = 2;
  const FreeSpaceCheck check(p);
  EXPECT_FALSE(check.seenThrough(1, 0));
  EXPECT_TRUE(check.seenThrough(2, 0));
  EXPECT_FALSE(check.seenThrough(2, 2));
  EXPECT_TRUE(check.seenThrough(3, 2));
}

// Step 2 on a room with a leg 1 m ahead, the sensor moving sideways 5 cm a
// frame (10 Hz), so that earlier frames see behind the leg, every return
// valid (step 1 found nothing): in the last frame one beam beside the leg is
// made a mixed return, halfway between the leg and the wall behind. In the
// first `earlier_near` frames (all 0.25 m+ from the last) one beam ends where
// that mixed return will lie, as another viewpoint's mixed return of the leg
// may. Returns the labels of the last frame for both implementations, the
// beams of the mixed return and of the leg, and the votes each cache holds
// where the mixed return lies once the last frame joined it.
//
// `kAlone`: the last frame's mixed return is instead a lone return halfway to
// the far wall, away from the leg (beams on both sides go on to the wall): a
// thin leg's mixed return, or a pane's direct one, in one frame.
// `kAloneBesideNoReturn`: the same with the next beam returning nothing.
// `kAloneBehindAPost`: the same behind a post 1 cm thick standing on that
// beam 1 m out, which the beams beside it miss: the post's mixed return.
struct LastFrame {
  std::vector<std::uint8_t> reference, fast;
  std::size_t mixed = 0, leg = 0;
  int reference_votes = 0, fast_votes = 0;  // around the mixed return
};

// Votes in the cell of p and the eight around it: p may lie on a cell's edge,
// and the filter computes its world point by another path than the test.
// Nothing else lies that near the mixed return: other frames saw through it.
int votesAround(const PenetrationGrid& grid, const Eigen::Vector2d& p) {
  const CellIndex c = grid.cellOf(p);
  int votes = 0;
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy) votes += grid.count({c.x + dx, c.y + dy});
  return votes;
}

enum class MixedReturn { kBesideTheLeg, kAlone, kAloneBesideNoReturn, kAloneBehindAPost };

LastFrame filterWithAMixedReturn(const PenetrationFilterParams& p, int earlier_near = 0,
                                 MixedReturn where = MixedReturn::kBesideTheLeg) {
  const SensorInfo sensor = test::simpleSensor();
  constexpr int kFrames = 16;
  const auto poseOf = [](int k) { return Pose2{0.0, 0.05 * k, 0.0}; };
  World world = World{}
                    .wall({3, -3}, {3, 3})
                    .wall({-3, -3}, {3, -3})
                    .wall({-3, 3}, {3, 3})
                    .wall({-3, -3}, {-3, 3})
                    .leg({1.0, 0.0}, 0.03);
  constexpr double kAloneBearing = 30.0 * kDeg;
  if (where == MixedReturn::kAloneBehindAPost)
    world.leg(Eigen::Vector2d(0.0, poseOf(kFrames - 1).y) +
                  Eigen::Vector2d(std::cos(kAloneBearing), std::sin(kAloneBearing)),
              0.01);
  auto reference = makePenetrationFilter(p, Implementation::kReference);
  auto fast = makePenetrationFilter(p, Implementation::kFast);
  LastFrame out;
  // The frames with an earlier return must count as taken from elsewhere.
  if (earlier_near > 0) {
    EXPECT_GE(poseOf(kFrames - 1).y - poseOf(earlier_near - 1).y, p.rescue_min_baseline);
  }
  // The mixed return of the last frame: the first beam past the leg's edge
  // that reaches the wall, pulled halfway to the leg.
  const auto mixReturn = [&](Scan& scan) {
    if (where != MixedReturn::kBesideTheLeg) {
      out.mixed = test::beamTowards(scan, sensor, kAloneBearing);
      // Halfway to the wall (behind the post, whose range the beam gives).
      if (where == MixedReturn::kAloneBehindAPost) scan.ranges[out.mixed] = scan.ranges[out.mixed + 1];
      scan.ranges[out.mixed] *= 0.5;
      if (where == MixedReturn::kAloneBesideNoReturn) scan.ranges[out.mixed + 1] = kNaN;
      return;
    }
    out.mixed = test::beamTowards(scan, sensor, std::atan2(-poseOf(kFrames - 1).y, 1.0));
    while (scan.ranges[out.mixed] < 2.0) ++out.mixed;
    scan.ranges[out.mixed] = 0.5 * (scan.ranges[out.mixed - 1] + scan.ranges[out.mixed]);
  };
  Scan last = castScan(world, poseOf(kFrames - 1), sensor, 360, 0.1 * (kFrames - 1));
  mixReturn(last);
  const double bearing = beamWorldAngle(last, sensor, out.mixed);
  const Eigen::Vector2d mixed_at = Eigen::Vector2d(0.0, poseOf(kFrames - 1).y) +
                                   last.ranges[out.mixed] * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
  for (int k = 0; k < kFrames; ++k) {
    const Pose2 pose = poseOf(k);
    Scan scan = castScan(world, pose, sensor, 360, 0.1 * k);
    out.leg = test::beamTowards(scan, sensor, std::atan2(-pose.y, 1.0));
    if (k == kFrames - 1) mixReturn(scan);
    if (k < earlier_near) {
      const Eigen::Vector2d to = mixed_at - Eigen::Vector2d(pose.x, pose.y);
      scan.ranges[test::beamTowards(scan, sensor, std::atan2(to.y(), to.x()))] = to.norm();
    }
    std::vector<std::uint8_t> labels(scan.size());
    for (std::size_t i = 0; i < scan.size(); ++i)
      labels[i] = scan.hasReturn(i) ? kValid : static_cast<std::uint8_t>(PointCode::kNoReturn);
    out.reference = labels;
    out.fast = labels;
    reference->apply(scan, sensor, out.reference);
    fast->apply(scan, sensor, out.fast);
  }
  // Every frame joined the cache (0.1 s apart, none expired), the last one too.
  EXPECT_EQ(fast->cachedFrames(), static_cast<std::size_t>(kFrames));
  EXPECT_EQ(reference->cachedFrames(), static_cast<std::size_t>(kFrames));
  out.reference_votes = votesAround(reference->grid(), mixed_at);
  out.fast_votes = votesAround(fast->grid(), mixed_at);
  return out;
}

TEST(FreeSpaceCheck, StepTwoRemovesAMixedReturnAndKeepsTheLeg) {
  const LastFrame on = filterWithAMixedReturn(PenetrationFilterParams{});
  EXPECT_EQ(on.reference, on.fast) << "both implementations run the same check";
  EXPECT_EQ(on.fast[on.mixed], kJump) << "earlier frames from 0.25 m+ away saw the wall through it";
  EXPECT_EQ(on.fast[on.leg], kValid) << "the leg blocked those frames' beams: it is hit, not seen through";
  EXPECT_EQ(std::count(on.fast.begin(), on.fast.end(), kJump), 1) << "nothing else in the room is in free space";

  PenetrationFilterParams off;
  off.free_space_check = false;
  EXPECT_EQ(filterWithAMixedReturn(off).fast[on.mixed], kValid) << "the paper's step 2 keeps it";

  PenetrationFilterParams veto_one;
  veto_one.free_space_veto_count = 1;
  EXPECT_EQ(filterWithAMixedReturn(veto_one).fast[on.mixed], kJump) << "no return from elsewhere near it";

  PenetrationFilterParams no_parallax;
  no_parallax.rescue_min_baseline = 2.0;  // no cached frame is that far
  EXPECT_EQ(filterWithAMixedReturn(no_parallax).fast[on.mixed], kValid)
      << "frames from (nearly) the same place say nothing";
}

// Beyond the paper 39: other viewpoints see through glass, so the check also
// marks a pane's occasional direct return, a lone one; it still votes, so
// that the pane's returns pile up in the cache over the frames. One beside a
// single depth edge (mixed at an edge) does not, nor one beside a beam
// without a return, nor one with a cached object in its footprint in front
// of it (that object's mixed return).
TEST(FreeSpaceCheck, ALoneReturnItMarksStillVotesInTheCache) {
  const PenetrationFilterParams defaults;
  ASSERT_TRUE(defaults.free_space_lone_returns_vote);
  const LastFrame alone = filterWithAMixedReturn(defaults, 0, MixedReturn::kAlone);
  EXPECT_EQ(alone.reference, alone.fast);
  EXPECT_EQ(alone.fast[alone.mixed], kJump) << "earlier frames saw the wall through it";
  EXPECT_EQ(alone.fast_votes, 1) << "marked, and still a vote where it lies";
  EXPECT_EQ(alone.reference_votes, 1);

  const LastFrame beside = filterWithAMixedReturn(defaults);
  EXPECT_EQ(beside.reference, beside.fast);
  EXPECT_EQ(beside.fast[beside.mixed], kJump);
  EXPECT_EQ(beside.fast_votes, 0) << "nearer than the wall on one side only: a mixed return at an edge";
  EXPECT_EQ(beside.reference_votes, 0);

  const LastFrame open = filterWithAMixedReturn(defaults, 0, MixedReturn::kAloneBesideNoReturn);
  EXPECT_EQ(open.reference, open.fast);
  EXPECT_EQ(open.fast[open.mixed], kJump) << "the wall on its other side was seen through it";
  EXPECT_EQ(open.fast_votes, 0) << "beside a beam without a return: not in front of both sides";
  EXPECT_EQ(open.reference_votes, 0);

  const LastFrame post = filterWithAMixedReturn(defaults, 0, MixedReturn::kAloneBehindAPost);
  EXPECT_EQ(post.reference, post.fast);
  EXPECT_EQ(post.fast[post.mixed], kJump) << "earlier frames saw the wall through it, past the post";
  EXPECT_EQ(post.fast_votes, 0) << "the post the cache holds stands in its footprint: the post's mixed return";
  EXPECT_EQ(post.reference_votes, 0);

  PenetrationFilterParams off;
  off.free_space_lone_returns_vote = false;
  const LastFrame alone_off = filterWithAMixedReturn(off, 0, MixedReturn::kAlone);
  EXPECT_EQ(alone_off.reference, alone_off.fast);
  EXPECT_EQ(alone_off.fast[alone_off.mixed], kJump) << "the switch changes the votes, not the label";
  EXPECT_EQ(alone_off.fast_votes, 0);
  EXPECT_EQ(alone_off.reference_votes, 0);
}

// Returns of other frames near the point vouch for a surface there, but one
// alone (another viewpoint's mixed return of the same leg) is not enough at
// the default free_space_veto_count of 2 (docs/beyond-the-paper.md, 19).
TEST(FreeSpaceCheck, OneReturnFromElsewhereNearItDoesNotVetoTheCheck) {
  const PenetrationFilterParams defaults;
  ASSERT_EQ(defaults.free_space_veto_count, 2);
  const LastFrame one = filterWithAMixedReturn(defaults, 1);
  EXPECT_EQ(one.reference, one.fast);
  EXPECT_EQ(one.fast[one.mixed], kJump) << "one earlier return near it: still checked, still seen through";
  const LastFrame two = filterWithAMixedReturn(defaults, 2);
  EXPECT_EQ(two.reference, two.fast);
  EXPECT_EQ(two.fast[two.mixed], kValid) << "two earlier returns near it vouch for a surface";

  PenetrationFilterParams veto_one;
  veto_one.free_space_veto_count = 1;
  const LastFrame vetoed = filterWithAMixedReturn(veto_one, 1);
  EXPECT_EQ(vetoed.fast[vetoed.mixed], kValid) << "with 1, any return from elsewhere vetoes";
}

}  // namespace
}  // namespace scanfilter
