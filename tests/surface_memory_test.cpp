// straightSegments and SurfaceMemory: which surfaces a frame's returns make,
// which are remembered, and which later returns lie beyond them.
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/stamp.hpp"
#include "scanfilter/straight_segments.hpp"
#include "scanfilter/surface_memory.hpp"

namespace scanfilter {
namespace {

const Eigen::Vector2d kOrigin = Eigen::Vector2d::Zero();
const Eigen::Vector2d kNoReturn{std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};

// Returns every `step` m from `from` to `to` (both included), in beam order.
void appendLine(std::vector<Eigen::Vector2d>& points, Eigen::Vector2d from, Eigen::Vector2d to, double step = 0.05) {
  const int n = static_cast<int>(std::lround((to - from).norm() / step));
  for (int k = 0; k <= n; ++k) points.push_back(from + (to - from) * (static_cast<double>(k) / n));
}

BeamMask usableReturns(const std::vector<Eigen::Vector2d>& points) {
  BeamMask usable(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) usable.set(i, std::isfinite(points[i].x()));
  return usable;
}

std::vector<StraightSegment> segmentsOf(const std::vector<Eigen::Vector2d>& points) {
  return straightSegments(points, usableReturns(points), kOrigin, StraightSegmentParams{});
}

Stamp at(double seconds) { return Stamp::fromNanoseconds(static_cast<std::int64_t>(std::llround(seconds * 1e9))); }

TEST(StraightSegments, SplitsARunAtACorner) {
  std::vector<Eigen::Vector2d> points;
  appendLine(points, {-1.0, 1.0}, {1.0, 1.0});
  points.pop_back();  // the corner once
  appendLine(points, {1.0, 1.0}, {1.0, -1.0});
  const auto segments = segmentsOf(points);
  ASSERT_EQ(segments.size(), 2u);
  EXPECT_LT((segments[0].a - Eigen::Vector2d(-1.0, 1.0)).norm(), 0.01);
  EXPECT_LT((segments[0].b - Eigen::Vector2d(1.0, 1.0)).norm(), 0.05);
  EXPECT_LT((segments[1].b - Eigen::Vector2d(1.0, -1.0)).norm(), 0.01);
}

TEST(StraightSegments, NeedsEnoughReturnsOverEnoughLengthCloseTogether) {
  std::vector<Eigen::Vector2d> few, short_run, sparse;
  appendLine(few, {0.0, 1.0}, {0.5, 1.0}, 0.125);       // 5 returns over 0.5 m
  appendLine(short_run, {0.0, 1.0}, {0.2, 1.0}, 0.02);  // 11 returns over 0.2 m
  appendLine(sparse, {0.0, 1.0}, {2.0, 1.0}, 0.2);      // spaced wider than max_spacing
  EXPECT_TRUE(segmentsOf(few).empty());
  EXPECT_TRUE(segmentsOf(short_run).empty());
  EXPECT_TRUE(segmentsOf(sparse).empty());
  std::vector<Eigen::Vector2d> enough;
  appendLine(enough, {0.0, 1.0}, {0.5, 1.0}, 0.1);  // 6 returns over 0.5 m
  EXPECT_EQ(segmentsOf(enough).size(), 1u);
}

TEST(StraightSegments, MarksTheEndsTheFrameSawPast) {
  std::vector<Eigen::Vector2d> points;
  points.emplace_back(-0.6, 3.0);  // farther than the wall's first return: the wall ends there
  appendLine(points, {-0.5, 1.0}, {0.5, 1.0});
  points.emplace_back(0.55, 0.5);  // nearer: something hides the wall, which may go on
  const auto segments = segmentsOf(points);
  ASSERT_EQ(segments.size(), 1u);
  EXPECT_TRUE(segments[0].a_seen_past);
  EXPECT_FALSE(segments[0].b_seen_past);
  points.front() = kNoReturn;  // no return says nothing
  EXPECT_FALSE(segmentsOf(points)[0].a_seen_past);
}

// A full turn whose first beam points along +x: the wall x = 1 lies across
// its seam, half at the first beams and half at the last.
TEST(StraightSegments, AFullTurnJoinsAWallAcrossItsSeam) {
  std::vector<Eigen::Vector2d> turn;
  for (int deg = 0; deg < 360; ++deg) {
    const double a = degreesToRadians(deg);
    const Eigen::Vector2d direction{std::cos(a), std::sin(a)};
    turn.push_back(std::abs(deg % 360 - (deg < 180 ? 0 : 360)) <= 30 ? direction / direction.x() : kNoReturn);
  }
  const auto across = straightSegments(turn, usableReturns(turn), kOrigin, StraightSegmentParams{}, true);
  ASSERT_EQ(across.size(), 1u);
  EXPECT_NEAR(std::abs(across[0].a.y() - across[0].b.y()), 2.0 * std::tan(degreesToRadians(30)), 0.01);
  EXPECT_EQ(straightSegments(turn, usableReturns(turn), kOrigin, StraightSegmentParams{}, false).size(), 2u)
      << "a partial scan's ends are no neighbours";
}

// A memory that has seen the wall y = 1, x in [-1, 1], from the origin at t = 0.
SurfaceMemory memoryOfAWall(const SurfaceMemoryParams& params = {}) {
  SurfaceMemory memory(params);
  std::vector<Eigen::Vector2d> wall;
  appendLine(wall, {-1.0, 1.0}, {1.0, 1.0});
  memory.forget(kOrigin, at(0.0));
  memory.remember(wall, usableReturns(wall), kOrigin, at(0.0));
  return memory;
}

TEST(SurfaceMemory, AReturnBeyondARememberedSurfaceWasSeenThroughIt) {
  const SurfaceMemory memory = memoryOfAWall();
  ASSERT_EQ(memory.size(), 1u);
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.0, 2.0}, at(1.0)));    // a ghost 1 m behind a mirror
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {0.0, 1.1}, at(1.0)));   // on the wall, within the margin
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {0.0, 0.5}, at(1.0)));   // in front of it
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {1.9, 1.9}, at(1.0)));   // beside its end (crosses at x = 1.0)
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {1.9, 2.0}, at(1.0)));   // within end_margin (x = 0.95)
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {1.7, 2.0}, at(1.0)));    // inside it (x = 0.85)
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {3.0, 2.0}, at(1.0)));   // past its end
  // From the other side the wall is in front of the sensor, not behind the return.
  EXPECT_FALSE(memory.liesBeyondASurface({0.0, 2.0}, {0.0, 1.5}, at(1.0)));
}

// What bench/misdetected_error_breakdown asks: what the memory holds near a
// point, live or past its lifetime (judging ignores those before forget()).
TEST(SurfaceMemory, SaysWhatItHoldsNearAPoint) {
  SurfaceMemoryParams params;
  params.lifetime = 5.0;
  const SurfaceMemory memory = memoryOfAWall(params);
  const auto on_it = memory.heldNear({0.0, 1.03}, at(1.0), 0.05);
  ASSERT_TRUE(on_it);
  EXPECT_TRUE(on_it->alive);
  EXPECT_FALSE(on_it->pane_or_mirror);  // a wall seen as a straight run, never confirmed
  EXPECT_FALSE(memory.heldNear({0.0, 1.2}, at(1.0), 0.05));   // off its line
  EXPECT_FALSE(memory.heldNear({1.5, 1.0}, at(1.0), 0.05));   // past its end
  const auto expired = memory.heldNear({0.0, 1.0}, at(6.0), 0.05);
  ASSERT_TRUE(expired);
  EXPECT_FALSE(expired->alive);
}

TEST(SurfaceMemory, ForgetsWhatItDidNotSeeAgainWithinItsLifetime) {
  SurfaceMemoryParams params;
  params.lifetime = 5.0;
  SurfaceMemory memory = memoryOfAWall(params);
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.0, 2.0}, at(4.9)));
  // Judging alone (PenetrationFilter::judge changes no state) already
  // ignores it past its lifetime; forget() drops it.
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {0.0, 2.0}, at(5.1)));
  EXPECT_EQ(memory.size(), 1u);
  memory.forget(kOrigin, at(5.1));
  EXPECT_EQ(memory.size(), 0u);
}

TEST(SurfaceMemory, TheMarginGrowsWithRange) {
  SurfaceMemory memory(SurfaceMemoryParams{});
  std::vector<Eigen::Vector2d> far_wall;
  appendLine(far_wall, {-1.0, 5.0}, {1.0, 5.0});
  memory.remember(far_wall, usableReturns(far_wall), kOrigin, at(0.0));
  // 0.25 m behind it at 5.25 m: within 0.20 m + 2 cm/m, so on it.
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {0.0, 5.25}, at(1.0)));
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.0, 5.40}, at(1.0)));
  SurfaceMemoryParams flat;
  flat.surface_margin_per_m = 0.0;
  SurfaceMemory flat_memory(flat);
  flat_memory.remember(far_wall, usableReturns(far_wall), kOrigin, at(0.0));
  EXPECT_TRUE(flat_memory.liesBeyondASurface(kOrigin, {0.0, 5.25}, at(1.0)));
}

TEST(SurfaceMemory, RemembersAFrameAtMostEveryMinInterval) {
  SurfaceMemory memory = memoryOfAWall();
  std::vector<Eigen::Vector2d> other;
  appendLine(other, {-1.0, -1.0}, {1.0, -1.0});
  memory.remember(other, usableReturns(other), kOrigin, at(0.1));
  EXPECT_EQ(memory.size(), 1u);
  memory.remember(other, usableReturns(other), kOrigin, at(0.3));
  EXPECT_EQ(memory.size(), 2u);
}

TEST(SurfaceMemory, ForgetsASurfaceTheSensorDroveThrough) {
  SurfaceMemory memory = memoryOfAWall();
  memory.forget({0.0, 1.5}, at(1.0));
  EXPECT_EQ(memory.size(), 0u);
}

// A frame from `from`, one beam a degree from `from_deg` to `to_deg` off +y
// (towards +x), each ending where `range_at(degrees)` says (NaN: no return).
template <typename RangeAt>
std::vector<Eigen::Vector2d> fanOfBeams(const Eigen::Vector2d& from, int from_deg, int to_deg, RangeAt range_at) {
  std::vector<Eigen::Vector2d> points;
  for (int deg = from_deg; deg <= to_deg; ++deg) {
    const double a = degreesToRadians(deg);
    points.push_back(from + Eigen::Vector2d(std::sin(a), std::cos(a)) * range_at(deg));
  }
  return points;
}
template <typename RangeAt>
std::vector<Eigen::Vector2d> fanOfBeams(int from_deg, int to_deg, RangeAt range_at) {
  return fanOfBeams(kOrigin, from_deg, to_deg, range_at);
}

// The range from y = `from_y` to the line y = `y` along a beam `deg` degrees off +y.
double toLineY(double y, int deg, double from_y = 0.0) { return (y - from_y) / std::cos(degreesToRadians(deg)); }

// The pane y = 2 seen from the origin, a beam a degree from -30 to 30 off
// +y; the beams from 3 to `hole_to_deg` degrees end at y = `behind_y`
// instead (NaN: no return).
std::vector<Eigen::Vector2d> paneWithAHole(double behind_y, int hole_to_deg = 7) {
  return fanOfBeams(-30, 30, [&](int deg) { return toLineY(deg >= 3 && deg <= hole_to_deg ? behind_y : 2.0, deg); });
}

std::vector<StraightSegment> segmentsAcrossGaps(const std::vector<Eigen::Vector2d>& points,
                                                const SurfaceAcrossGap& surface_across_gap,
                                                const StraightSegmentParams& params = {}) {
  return straightSegments(points, usableReturns(points), kOrigin, params, false, surface_across_gap);
}

const SurfaceAcrossGap kSurfaceEverywhere = [](const Eigen::Vector2d&, const Eigen::Vector2d&) { return true; };

TEST(StraightSegments, ARunGoesOnAcrossAHoleWhereASurfaceStandsElsewhere) {
  const auto pane = paneWithAHole(5.0);  // 0.21 m between the returns either side
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> asked;
  const auto across = segmentsAcrossGaps(pane, [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    asked.emplace_back(from, to);
    return true;
  });
  ASSERT_EQ(across.size(), 1u);
  EXPECT_NEAR(across[0].a.x(), -2.0 * std::tan(degreesToRadians(30)), 0.01);
  EXPECT_NEAR(across[0].b.x(), 2.0 * std::tan(degreesToRadians(30)), 0.01);
  ASSERT_EQ(asked.size(), 1u) << "asked once, about the returns either side of the hole";
  EXPECT_LT((asked[0].first - pane[32]).norm(), 1e-9);
  EXPECT_LT((asked[0].second - pane[38]).norm(), 1e-9);
  EXPECT_EQ(segmentsAcrossGaps(pane, [](const Eigen::Vector2d&, const Eigen::Vector2d&) { return false; }).size(), 2u)
      << "no surface there elsewhere: an opening";
  EXPECT_EQ(segmentsOf(pane).size(), 2u) << "nobody to ask";
  StraightSegmentParams off;
  off.max_gap = 0.0;
  EXPECT_EQ(segmentsAcrossGaps(pane, kSurfaceEverywhere, off).size(), 2u);
  const auto dark = paneWithAHole(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(segmentsAcrossGaps(dark, kSurfaceEverywhere).size(), 1u) << "beams without a return are a hole too";
}

// The segments of `points` across gaps where a surface stands everywhere are
// those without the question asked, and so are the ends the frame saw past
// (a run joined across a step and split again would lose them).
void expectNoGapBridged(const std::vector<Eigen::Vector2d>& points) {
  const auto asked = segmentsAcrossGaps(points, kSurfaceEverywhere), unasked = segmentsOf(points);
  ASSERT_EQ(asked.size(), unasked.size());
  for (std::size_t k = 0; k < asked.size(); ++k) {
    EXPECT_LT((asked[k].a - unasked[k].a).norm(), 1e-9) << "segment " << k;
    EXPECT_LT((asked[k].b - unasked[k].b).norm(), 1e-9) << "segment " << k;
    EXPECT_EQ(asked[k].a_seen_past, unasked[k].a_seen_past) << "segment " << k;
    EXPECT_EQ(asked[k].b_seen_past, unasked[k].b_seen_past) << "segment " << k << ": the hole is seen past";
  }
}

TEST(StraightSegments, OnlyANarrowHoleSeenThroughBetweenReturnsOfOneLine) {
  ASSERT_EQ(segmentsAcrossGaps(paneWithAHole(5.0), kSurfaceEverywhere).size(), 1u);
  {
    SCOPED_TRACE("0.39 m and 11 degrees between the returns either side: past the angle a 0.30 m gap subtends");
    expectNoGapBridged(paneWithAHole(5.0, 12));
  }
  {
    SCOPED_TRACE("something in front: no hole seen through");
    expectNoGapBridged(paneWithAHole(1.0));
  }
  auto step = paneWithAHole(5.0);
  for (int deg = 8; deg <= 30; ++deg) step[static_cast<std::size_t>(deg + 30)] *= 2.1 / 2.0;  // on at y = 2.1
  {
    SCOPED_TRACE("a step to another surface");
    expectNoGapBridged(step);
  }
}

TEST(StraightSegments, AHoleOfBeamsWithoutAReturnAndBeamsSeenThroughIsOneHole) {
  auto pane = paneWithAHole(5.0);
  for (const int deg : {3, 4}) pane[static_cast<std::size_t>(deg + 30)] = kNoReturn;
  EXPECT_EQ(segmentsAcrossGaps(pane, kSurfaceEverywhere).size(), 1u);
}

TEST(StraightSegments, ARunTooShortToGiveALineDoesNotCrossAHole) {
  // Three returns (0 to 2 degrees, 7 cm) before a hole of 21 cm: their
  // direction is too short a base to carry the line across.
  const auto pane = fanOfBeams(0, 30, [](int deg) { return toLineY(deg >= 3 && deg <= 7 ? 5.0 : 2.0, deg); });
  SCOPED_TRACE("three returns before the hole");
  expectNoGapBridged(pane);
}

// The wall y = 2 from 0 to 60 degrees, seen through at 55 and 56: the
// returns either side of the hole lie 0.33 m apart but only 3 degrees, well
// inside the 5 degrees a 0.30 m gap subtends at their 3.4 m: max_gap decides.
TEST(StraightSegments, MaxGapIsTheLongestHoleCrossed) {
  const auto wall = fanOfBeams(0, 60, [](int deg) { return toLineY(deg == 55 || deg == 56 ? 5.0 : 2.0, deg); });
  {
    SCOPED_TRACE("0.33 m: longer than the default max_gap");
    expectNoGapBridged(wall);
  }
  StraightSegmentParams longer;
  longer.max_gap = 0.40;
  EXPECT_EQ(segmentsAcrossGaps(wall, kSurfaceEverywhere, longer).size(), 1u);
}

// A full turn whose first beam points along +x at the wall x = 1.5, seen
// from -30 to 30 degrees and through it from -2 to 2: the hole lies at the
// scan's seam, where the walk along the beams ends and begins again.
TEST(StraightSegments, AFullTurnCrossesAHoleAtItsSeam) {
  std::vector<Eigen::Vector2d> turn;
  for (int deg = 0; deg < 360; ++deg) {
    const int off = deg < 180 ? deg : deg - 360;
    const double a = degreesToRadians(deg);
    const Eigen::Vector2d direction{std::cos(a), std::sin(a)};
    const double x = std::abs(off) <= 2 ? 4.0 : 1.5;
    turn.push_back(std::abs(off) <= 30 ? direction * (x / direction.x()) : kNoReturn);
  }
  const auto across = straightSegments(turn, usableReturns(turn), kOrigin, StraightSegmentParams{}, true,
                                       kSurfaceEverywhere);
  ASSERT_EQ(across.size(), 1u);
  EXPECT_NEAR(std::abs(across[0].a.y() - across[0].b.y()), 3.0 * std::tan(degreesToRadians(30)), 0.01);
  EXPECT_EQ(straightSegments(turn, usableReturns(turn), kOrigin, StraightSegmentParams{}, true).size(), 2u)
      << "nobody to ask";
}

// A door that opened, a person who walked off: the remembered wall y = 1 is
// seen through head-on, where a mirror or a pane would have returned the
// beam, and is forgotten. Seen through only obliquely (ghosts behind a
// mirror), or with a return on it head-on, it stays.
TEST(SurfaceMemory, ForgetsASurfaceSeenThroughHeadOn) {
  const auto forgetsAfter = [](const std::vector<Eigen::Vector2d>& frame, const SurfaceMemoryParams& params = {}) {
    SurfaceMemory memory = memoryOfAWall(params);
    memory.forgetSeenThroughHeadOn(frame, usableReturns(frame), kOrigin);
    return memory.size() == 0;
  };
  const auto behind = [](int deg) { return toLineY(2.0, deg); };  // a wall 1 m behind it
  EXPECT_TRUE(forgetsAfter(fanOfBeams(-30, 30, behind)));

  // A mirror: returns on it within 2° of its normal, ghosts elsewhere.
  EXPECT_FALSE(forgetsAfter(fanOfBeams(-30, 30, [](int deg) { return toLineY(std::abs(deg) <= 2 ? 1.0 : 2.0, deg); })));
  // Ghosts only off the normal, no return within 5° of it (head_on_deg).
  const auto oblique = [](int deg) { return std::abs(deg) <= 5 ? std::nan("") : toLineY(2.0, deg); };
  EXPECT_FALSE(forgetsAfter(fanOfBeams(-30, 30, oblique)));
  // One beam through head-on is not enough (head_on_through_beams: 2).
  const auto one = [](int deg) { return deg == 0 || std::abs(deg) > 5 ? toLineY(2.0, deg) : std::nan(""); };
  EXPECT_FALSE(forgetsAfter(fanOfBeams(-30, 30, one)));
  const auto two = [](int deg) { return deg == 0 || deg == 1 || std::abs(deg) > 5 ? toLineY(2.0, deg) : std::nan(""); };
  EXPECT_TRUE(forgetsAfter(fanOfBeams(-30, 30, two)));
  // Something in front of the wall hides it: that says nothing of it.
  EXPECT_FALSE(forgetsAfter(fanOfBeams(-30, 30, [](int deg) { return toLineY(0.5, deg); })));

  // A head-on return on its line past its end (the wall goes on, and the
  // remembered stretch does not reach there) says nothing of it either.
  SurfaceMemory memory = memoryOfAWall();
  const Eigen::Vector2d beside_end{2.0, 0.0};
  const auto past_end = fanOfBeams(beside_end, -3, 3, [](int deg) { return toLineY(1.0, deg); });
  memory.forgetSeenThroughHeadOn(past_end, usableReturns(past_end), beside_end);
  EXPECT_EQ(memory.size(), 1u);

  SurfaceMemoryParams never;
  never.head_on_through_beams = 0;
  EXPECT_FALSE(forgetsAfter(fanOfBeams(-30, 30, behind), never));
}

// The sensor's perpendicular meets the wall's line just past its end, and
// head-on beams (within 5° of the normal) cross the wall inside it: the
// wall stays. Only a surface the sensor faces is judged; counting these too
// lost more re-observed returns on the Mines logs (docs/beyond-the-paper.md, 26).
TEST(SurfaceMemory, AWallSeenThroughHeadOnOnlyPastItsEndStays) {
  SurfaceMemory memory = memoryOfAWall();
  const Eigen::Vector2d near_end{1.1, -3.0};  // 4 m from y = 1: head-on beams cross x in [0.75, 1.45]
  const auto frame = fanOfBeams(near_end, -30, 30, [](int deg) { return toLineY(3.0, deg, -3.0); });  // 2 m behind
  memory.forgetSeenThroughHeadOn(frame, usableReturns(frame), near_end);
  EXPECT_EQ(memory.size(), 1u);
}

TEST(SurfaceMemory, DoesNotRememberSurfacesSeenAtGrazingIncidence) {
  SurfaceMemory memory(SurfaceMemoryParams{});
  std::vector<Eigen::Vector2d> wall;
  appendLine(wall, {2.0, 0.5}, {4.0, 0.5});  // the beam to its middle meets it at 9.5°
  memory.remember(wall, usableReturns(wall), kOrigin, at(0.0));
  EXPECT_EQ(memory.size(), 0u);
}

TEST(SurfaceMemory, ASurfaceSeenAgainMovesToWhereTheNewFrameSeesIt) {
  SurfaceMemory memory = memoryOfAWall();
  // Drifted odometry: the same wall 0.25 m farther, only its middle seen.
  std::vector<Eigen::Vector2d> again;
  appendLine(again, {-0.3, 1.25}, {0.3, 1.25});
  memory.forget(kOrigin, at(1.0));
  memory.remember(again, usableReturns(again), kOrigin, at(1.0));
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {0.8, 1.25}, at(1.0)));  // on the wall where it is now
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.8, 2.25}, at(1.0)));   // the part not seen again is still held
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.45, 2.25}, at(1.0)));  // no end margin where they join (x = 0.25)
}

// The wall y = 1 seen piece by piece from the origin, each piece from
// `from_x` to `to_x` in beam order (reversed: scanned the other way).
struct Piece {
  double from_x, to_x, t;
};
void seePieces(SurfaceMemory& memory, const std::vector<Piece>& pieces) {
  for (const Piece& piece : pieces) {
    std::vector<Eigen::Vector2d> points;
    appendLine(points, {piece.from_x, 1.0}, {piece.to_x, 1.0});
    memory.forget(kOrigin, at(piece.t));
    memory.remember(points, usableReturns(points), kOrigin, at(piece.t));
  }
}

// The sensor drives along a mirror and sees it piece by piece (near its
// normal only): each frame overlaps the last one's piece but not the one
// before. Where two remembered pieces join, neither has an end margin, however
// many frames later, whichever way each piece was scanned: only an end a
// frame saw has one.
TEST(SurfaceMemory, PiecesRememberedOneAfterAnotherJoinWithoutAnEndMargin) {
  for (const bool reversed : {false, true}) {
    SurfaceMemory memory{SurfaceMemoryParams{}};
    // Remembered after the second piece: [-1, -0.5] and [-0.5, 0.5]; the
    // third overlaps [-0.5, 0.5] only, so [-0.5, 0.0] joins [-1, -0.5].
    if (reversed) seePieces(memory, {{-1.0, 0.0, 0.0}, {0.5, -0.5, 1.0}, {0.0, 1.0, 2.0}});
    else seePieces(memory, {{-1.0, 0.0, 0.0}, {-0.5, 0.5, 1.0}, {0.0, 1.0, 2.0}});
    const double crossing_at_join = -0.45;  // within end_margin (0.10) of the join at x = -0.5
    EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {2.0 * crossing_at_join, 2.0}, at(2.0))) << reversed;
    EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {2.0 * -0.55, 2.0}, at(2.0))) << reversed;  // the other side
    EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {2.0 * -0.95, 2.0}, at(2.0))) << reversed;  // a seen end
  }
}

// A piece gone (here driven through: a door that opened) leaves the piece
// it joined with an end there again, margin and all.
TEST(SurfaceMemory, AJoinWhosePartnerIsGoneIsAnEndAgain) {
  SurfaceMemory memory{SurfaceMemoryParams{}};
  seePieces(memory, {{-1.0, 0.0, 0.0}, {-0.5, 0.5, 1.0}});  // [-1, -0.5] joins [-0.5, 0.5]
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {2.0 * -0.45, 2.0}, at(1.0)));
  memory.forget({-1.5, 2.0}, at(1.5));  // through [-1, -0.5], at x = -0.75
  memory.forget(kOrigin, at(2.0));      // and back
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {2.0 * -0.75, 2.0}, at(2.0))) << "the door is open";
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {2.0 * -0.45, 2.0}, at(2.0))) << "beside the jamb: the end margin";
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {2.0 * -0.35, 2.0}, at(2.0)));
}

TEST(SurfaceMemory, AStretchNotSeenAgainExpiresWhenItsTimeIsUp) {
  SurfaceMemory memory = memoryOfAWall();  // seen at 0 s, remembered for 20 s
  std::vector<Eigen::Vector2d> middle;
  appendLine(middle, {-0.3, 1.0}, {0.3, 1.0});
  memory.forget(kOrigin, at(15.0));
  memory.remember(middle, usableReturns(middle), kOrigin, at(15.0));
  memory.forget(kOrigin, at(21.0));
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.0, 2.0}, at(21.0)));   // seen again at 15 s
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {0.8, 2.0}, at(21.0)));  // last seen at 0 s
}

TEST(SurfaceMemory, MergesOnlySurfacesOfOneDirection) {
  SurfaceMemory memory = memoryOfAWall();
  std::vector<Eigen::Vector2d> tilted;  // 20° to the wall, through its middle
  appendLine(tilted, {-0.5, 1.0 - 0.5 * std::tan(0.349)}, {0.5, 1.0 + 0.5 * std::tan(0.349)});
  memory.remember(tilted, usableReturns(tilted), kOrigin, at(1.0));
  EXPECT_EQ(memory.size(), 2u);
}

TEST(SurfaceMemory, MergesASurfaceSeenInTheOtherDirection) {
  SurfaceMemory memory = memoryOfAWall();  // remembered from x = -1 to 1
  std::vector<Eigen::Vector2d> reversed;   // the scan runs the other way, 0.1 m farther
  appendLine(reversed, {0.5, 1.1}, {-0.5, 1.1});
  memory.remember(reversed, usableReturns(reversed), kOrigin, at(1.0));
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {0.0, 1.1}, at(1.0)));
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.8, 2.0}, at(1.0)));
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {-0.8, 2.0}, at(1.0)));
}

TEST(SurfaceMemory, ASurfaceSeenAgainEndsWhereTheNewFrameSawPastIt) {
  SurfaceMemory memory = memoryOfAWall();
  std::vector<Eigen::Vector2d> again;
  appendLine(again, {-1.0, 1.0}, {0.3, 1.0});
  appendLine(again, {0.6, 3.0}, {1.0, 3.0});  // beyond x = 0.3: a door open now
  memory.forget(kOrigin, at(1.0));
  memory.remember(again, usableReturns(again), kOrigin, at(1.0));
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, {0.9, 2.0}, at(1.0)));  // through the doorway
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {-0.5, 3.0}, at(1.0)));
}

// Beyond the paper 34: a sparse line (a pane's scattered returns) at y =
// `distance` in front of the sensor, from x = -1 to 1, remembered at t = 0.
SurfaceMemory memoryOfASparseLine(const SurfaceMemoryParams& params, double distance = 1.0) {
  SurfaceMemory memory(params);
  const std::vector<StraightSegment> found = {{{-1.0, distance}, {1.0, distance}, false, false}};
  memory.rememberSegments(found, kOrigin, at(0.0), 0.0);
  return memory;
}

SurfaceMemoryParams panesRememberedLonger() {
  SurfaceMemoryParams params;
  params.lifetime = 5.0;
  params.specular_lifetime = 60.0;
  params.sparse_lifetime = params.lifetime;  // unconfirmed lines as any surface (40 has its own test)
  return params;
}

// What a frame at the origin sees of a pane at y = `distance`: returns on it
// at these x, and beams through it beyond its specular lobe (to y = 3 d).
std::vector<Eigen::Vector2d> aFrameFacing(std::initializer_list<double> xs, double distance = 1.0) {
  std::vector<Eigen::Vector2d> points;
  for (double x : xs) points.emplace_back(x, distance);
  for (double x : {-0.8, -0.6, 0.6, 0.8}) points.emplace_back(3.0 * x, 3.0 * distance);
  return points;
}

TEST(SurfaceMemory, ASparseLineSeenOnlyHeadOnIsAPaneAndOutlivesTheLifetime) {
  SurfaceMemory memory = memoryOfASparseLine(panesRememberedLonger());
  // The lobe at 1 m: tan(5°) + specular_confirm_distance = 0.19 m either side of the foot.
  const auto head_on = aFrameFacing({-0.05, 0.1});
  memory.confirmPanesAndMirrors(head_on, usableReturns(head_on), kOrigin);
  memory.forget(kOrigin, at(30.0));
  EXPECT_EQ(memory.size(), 1u);
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.0, 2.0}, at(30.0)));
  memory.forget(kOrigin, at(61.0));
  EXPECT_EQ(memory.size(), 0u) << "a pane expires after specular_lifetime";
}

TEST(SurfaceMemory, ASparseLineNoFrameConfirmedLivesTheSparseLifetime) {
  // Beyond the paper 40: a line of single cached returns is no surer than
  // the cache; a thin leg's mixed returns line up too.
  SurfaceMemoryParams params = panesRememberedLonger();
  params.sparse_lifetime = 2.0;
  SurfaceMemory unconfirmed = memoryOfASparseLine(params);
  unconfirmed.forget(kOrigin, at(1.5));
  EXPECT_TRUE(unconfirmed.liesBeyondASurface(kOrigin, {0.0, 2.0}, at(1.5)));
  unconfirmed.forget(kOrigin, at(2.5));
  EXPECT_EQ(unconfirmed.size(), 0u) << "gone after sparse_lifetime, not lifetime (5 s)";
  EXPECT_FALSE(unconfirmed.liesBeyondASurface(kOrigin, {0.0, 2.0}, at(2.5)));
  // Confirmed as a pane, it lives specular_lifetime.
  SurfaceMemory pane = memoryOfASparseLine(params);
  const auto head_on = aFrameFacing({0.0});
  pane.confirmPanesAndMirrors(head_on, usableReturns(head_on), kOrigin);
  pane.forget(kOrigin, at(30.0));
  EXPECT_EQ(pane.size(), 1u);
  // A wall a frame saw as a straight run lives the lifetime.
  SurfaceMemory wall = memoryOfAWall(params);
  wall.forget(kOrigin, at(4.0));
  EXPECT_EQ(wall.size(), 1u);
}

TEST(SurfaceMemory, TheLobeWidensWithDistance) {
  // At 3 m the lobe reaches 3 tan(5°) + 0.1 = 0.36 m: a return at x = 0.3 lies in it.
  SurfaceMemory memory = memoryOfASparseLine(panesRememberedLonger(), 3.0);
  const auto head_on = aFrameFacing({0.3}, 3.0);
  memory.confirmPanesAndMirrors(head_on, usableReturns(head_on), kOrigin);
  memory.forget(kOrigin, at(30.0));
  EXPECT_EQ(memory.size(), 1u);
}

TEST(SurfaceMemory, ASparseLineThatReturnsMostBeamsOffItsLobeIsNoPane) {
  // A row of chair legs returns at any angle: off the lobe (0.19 m) six
  // beams end on it, four pass through it (aFrameFacing's).
  SurfaceMemory memory = memoryOfASparseLine(panesRememberedLonger());
  const auto legs = aFrameFacing({0.0, 0.3, 0.45, 0.6, -0.3, -0.45, -0.6});
  memory.confirmPanesAndMirrors(legs, usableReturns(legs), kOrigin);
  memory.forget(kOrigin, at(6.0));
  EXPECT_EQ(memory.size(), 0u);
}

TEST(SurfaceMemory, AGlossySurfaceThatReturnsSomeBeamsOffItsLobeIsAMirror) {
  // Beyond the paper 35: a glossy wall returns a beam now and then at any
  // angle. Off the lobe one beam ends on it and four pass through it.
  const auto glossy = aFrameFacing({0.0, 0.6});
  const auto confirmedWithShare = [&](double share) {
    SurfaceMemoryParams params = panesRememberedLonger();
    params.specular_min_pass_share = share;
    SurfaceMemory memory = memoryOfASparseLine(params);
    memory.confirmPanesAndMirrors(glossy, usableReturns(glossy), kOrigin);
    memory.forget(kOrigin, at(6.0));
    return memory.size() == 1u;
  };
  EXPECT_TRUE(confirmedWithShare(0.5));
  EXPECT_TRUE(confirmedWithShare(0.79)) << "4 of 5 pass";
  EXPECT_FALSE(confirmedWithShare(0.81));
  EXPECT_FALSE(confirmedWithShare(1.0)) << "1: no beam off the lobe may end on it";
}

TEST(SurfaceMemory, AFrameConfirmsOnlyALineItFacesSeesOnAndSeesThrough) {
  const auto confirmedBy = [](const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& origin) {
    SurfaceMemory memory = memoryOfASparseLine(panesRememberedLonger());
    memory.confirmPanesAndMirrors(points, usableReturns(points), origin);
    memory.forget(kOrigin, at(6.0));
    return memory.size() == 1u;
  };
  // Just past its end the foot lies outside it: a return in what would be
  // the lobe, and beams through it at x = 0.5 and 0.2, do not count.
  const std::vector<Eigen::Vector2d> from_past_its_end = {{0.95, 1.0}, {-0.7, 3.0}, {-1.6, 3.0}};
  EXPECT_FALSE(confirmedBy(from_past_its_end, {1.1, 0.0}));
  const std::vector<Eigen::Vector2d> nothing_on_it = {{0.0, 3.0}, {-2.4, 3.0}, {2.4, 3.0}};
  EXPECT_FALSE(confirmedBy(nothing_on_it, kOrigin));
  // Returns on it in the lobe but no beam seen through it beyond the lobe:
  // a line the frame could not have seen elsewhere says nothing.
  const std::vector<Eigen::Vector2d> not_seen_through = {{0.0, 1.0}, {0.1, 1.0}};
  EXPECT_FALSE(confirmedBy(not_seen_through, kOrigin));
  EXPECT_TRUE(confirmedBy(aFrameFacing({0.0}), kOrigin));
}

TEST(SurfaceMemory, OnlySparseLinesAreConfirmedAndNeverLiveShorterThanTheLifetime) {
  // A wall a frame saw as a straight run is no sparse line: never a pane.
  SurfaceMemory wall = memoryOfAWall(panesRememberedLonger());
  const auto head_on = aFrameFacing({0.0});
  wall.confirmPanesAndMirrors(head_on, usableReturns(head_on), kOrigin);
  wall.forget(kOrigin, at(6.0));
  EXPECT_EQ(wall.size(), 0u);
  // With specular_lifetime below the lifetime nothing is confirmed: a pane
  // lives the lifetime, not the 3 s.
  SurfaceMemoryParams shorter = panesRememberedLonger();
  shorter.specular_lifetime = 3.0;
  SurfaceMemory memory = memoryOfASparseLine(shorter);
  memory.confirmPanesAndMirrors(head_on, usableReturns(head_on), kOrigin);
  memory.forget(kOrigin, at(4.0));
  EXPECT_EQ(memory.size(), 1u);
}

constexpr double kMinDepth = 0.16;  // MirrorGhostCheck's: twice its image_radius

TEST(SurfaceMemory, AReturnBeyondAMirrorsLineIsMirroredAcrossIt) {
  // Beyond the paper 35: the mirror at y = 1, x from -1 to 1, confirmed.
  SurfaceMemory memory = memoryOfASparseLine(panesRememberedLonger());
  const auto head_on = aFrameFacing({0.0});
  memory.confirmPanesAndMirrors(head_on, usableReturns(head_on), kOrigin);
  const auto crossingOf = [&](const Eigen::Vector2d& p) {
    std::optional<MirrorCrossing> found;
    memory.anyMirrorCrossed(kOrigin, p, at(1.0), kMinDepth, [&](const MirrorCrossing& c) {
      found = c;
      return true;
    });
    return found;
  };
  const std::optional<MirrorCrossing> on_it = crossingOf({0.5, 2.0});
  ASSERT_TRUE(on_it.has_value());
  EXPECT_TRUE(on_it->within_segment);
  EXPECT_NEAR(on_it->at.x(), 0.25, 1e-9);
  EXPECT_NEAR(on_it->at.y(), 1.0, 1e-9);
  EXPECT_NEAR(on_it->image.x(), 0.5, 1e-9);
  EXPECT_NEAR(on_it->image.y(), 0.0, 1e-9);
  const std::optional<MirrorCrossing> past_its_end = crossingOf({3.0, 2.0});
  ASSERT_TRUE(past_its_end.has_value()) << "the line goes on past the remembered stretch";
  EXPECT_FALSE(past_its_end->within_segment);
  EXPECT_NEAR(past_its_end->at.x(), 1.5, 1e-9);
  const std::optional<MirrorCrossing> in_the_end_margin = crossingOf({1.9, 2.0});
  ASSERT_TRUE(in_the_end_margin.has_value());
  EXPECT_FALSE(in_the_end_margin->within_segment) << "0.05 m inside its end: within end_margin";
  EXPECT_FALSE(crossingOf({0.5, 0.5}).has_value()) << "in front of it";
  EXPECT_FALSE(crossingOf({0.5, 1.1}).has_value()) << "0.1 m beyond it: nearer than min_depth";
  EXPECT_TRUE(crossingOf({0.6, 1.2}).has_value()) << "0.2 m beyond it, inside the surface margin (0.23 m)";
  EXPECT_FALSE(crossingOf(kNoReturn).has_value());
  EXPECT_FALSE(
      memory.anyMirrorCrossed({0.0, 2.0}, kNoReturn, at(1.0), kMinDepth, [](const MirrorCrossing&) { return true; }))
      << "no return, seen from the line's other side";
  // A line no frame confirmed is no mirror.
  SurfaceMemory unconfirmed = memoryOfASparseLine(panesRememberedLonger());
  EXPECT_FALSE(unconfirmed.anyMirrorCrossed(kOrigin, {0.5, 2.0}, at(1.0), kMinDepth,
                                            [](const MirrorCrossing&) { return true; }));
}

// Panes 2 m long across the y axis at y = each of `ys`, remembered at t = 0
// and confirmed by a frame at the origin that faces each head-on: a return
// on it, beams through it beyond its lobe.
SurfaceMemory panesConfirmedAt(const std::vector<double>& ys) {
  SurfaceMemory memory(panesRememberedLonger());
  std::vector<StraightSegment> lines;
  for (const double y : ys) lines.push_back({{-1.0, y}, {1.0, y}, false, false});
  memory.rememberSegments(lines, kOrigin, at(0.0), 0.0);
  for (const double y : ys) {
    std::vector<Eigen::Vector2d> frame = {{0.0, y}};
    for (double x : {-2.4, -1.8, 1.8, 2.4}) frame.emplace_back(x, 3.0 * y);
    memory.confirmPanesAndMirrors(frame, usableReturns(frame), kOrigin);
  }
  return memory;
}

// The first crossing anyMirrorCrossed reports for the return at p, seen
// from the origin at t = 1.
std::optional<MirrorCrossing> firstCrossing(const SurfaceMemory& memory, const Eigen::Vector2d& p) {
  std::optional<MirrorCrossing> first;
  memory.anyMirrorCrossed(kOrigin, p, at(1.0), kMinDepth, [&](const MirrorCrossing& c) {
    first = c;
    return true;
  });
  return first;
}

// Beyond the paper 43 asks which mirror a crossing was of: the ghost found
// in one proves that one alone.
TEST(SurfaceMemory, ACrossingSaysWhichMirrorItWasOf) {
  const SurfaceMemory memory = panesConfirmedAt({1.0, -1.0});
  const std::optional<MirrorCrossing> ahead = firstCrossing(memory, {0.5, 2.0});
  const std::optional<MirrorCrossing> ahead_past_its_end = firstCrossing(memory, {3.0, 2.0});
  const std::optional<MirrorCrossing> behind = firstCrossing(memory, {0.5, -2.0});
  ASSERT_TRUE(ahead && ahead_past_its_end && behind);
  EXPECT_EQ(ahead->surface, ahead_past_its_end->surface);
  EXPECT_NE(ahead->surface, behind->surface);
}

// Beyond the paper 44 asks how far past the remembered stretch a beam
// crossed a pane's line: a pane's ends are seen less than its middle.
TEST(SurfaceMemory, ACrossingSaysHowFarPastTheStretchItLies) {
  const SurfaceMemory memory = panesConfirmedAt({1.0});
  const std::optional<MirrorCrossing> on_it = firstCrossing(memory, {0.5, 2.0});      // crosses at x = 0.25
  const std::optional<MirrorCrossing> past_it = firstCrossing(memory, {3.0, 2.0});    // at x = 1.5
  const std::optional<MirrorCrossing> other_end = firstCrossing(memory, {-4.0, 2.0});  // at x = -2
  ASSERT_TRUE(on_it && past_it && other_end);
  EXPECT_NEAR(on_it->past_end, -0.75, 1e-9) << "0.75 m inside the nearer end";
  EXPECT_NEAR(past_it->past_end, 0.5, 1e-9);
  EXPECT_NEAR(other_end->past_end, 1.0, 1e-9);
}

TEST(SurfaceMemory, AConfirmedPaneStaysOneWhenSeenAgainAsASparseLine) {
  SurfaceMemory memory = memoryOfASparseLine(panesRememberedLonger());
  const auto head_on = aFrameFacing({0.0});
  memory.confirmPanesAndMirrors(head_on, usableReturns(head_on), kOrigin);
  // Seen again over part of it at t = 10: the new piece and the rest, merged, are the pane.
  const std::vector<StraightSegment> again = {{{0.0, 1.0}, {1.0, 1.0}, false, false}};
  memory.rememberSegments(again, kOrigin, at(10.0), 0.0);
  memory.forget(kOrigin, at(30.0));
  EXPECT_EQ(memory.size(), 2u);
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {-0.5, 2.0}, at(30.0))) << "the stretch not seen again";
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.5, 2.0}, at(30.0))) << "the stretch seen again";
}

// A pane at y = 1 confirmed by a frame at the origin at t = 0, never expiring.
SurfaceMemory memoryOfAPaneThatDrifts() {
  SurfaceMemoryParams params = panesRememberedLonger();
  params.specular_lifetime = 1e3;
  params.drift_margin_per_m = 0.01;
  params.drift_margin_deg_per_m = 0.5;
  SurfaceMemory memory = memoryOfASparseLine(params);
  const auto head_on = aFrameFacing({0.0});
  memory.confirmPanesAndMirrors(head_on, usableReturns(head_on), kOrigin);
  memory.forget(kOrigin, at(0.0));
  return memory;
}

TEST(SurfaceMemory, APanesMarginGrowsWithThePathDrivenSinceItWasSeen) {
  SurfaceMemory memory = memoryOfAPaneThatDrifts();
  const Eigen::Vector2d ghost{0.0, 1.6};  // 0.6 m behind: beyond surface_margin 0.2 + 0.02 per m
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, ghost, at(1.0)));
  // Drive to (10, -1) and back, never crossing it: 2 sqrt(101) = 20.1 m; the
  // margin grows by (0.01 + tan 0.5° · 1.6 m) · 20.1 m = 0.48 m.
  memory.forget({10.0, -1.0}, at(10.0));
  memory.forget(kOrigin, at(20.0));
  EXPECT_FALSE(memory.liesBeyondASurface(kOrigin, ghost, at(20.0)));
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.0, 2.5}, at(20.0))) << "a ghost farther behind still is";
  // Seen again: its margin starts again from the path driven now.
  const std::vector<StraightSegment> again = {{{-1.0, 1.0}, {1.0, 1.0}, false, false}};
  memory.rememberSegments(again, kOrigin, at(20.0), 0.0);
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, ghost, at(20.0)));
}

TEST(SurfaceMemory, AWallsMarginDoesNotGrow) {
  SurfaceMemoryParams params;
  params.lifetime = 1e3;
  params.drift_margin_per_m = 0.01;
  params.drift_margin_deg_per_m = 0.5;
  SurfaceMemory memory = memoryOfAWall(params);
  memory.forget({10.0, -1.0}, at(10.0));
  memory.forget(kOrigin, at(20.0));
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.0, 1.6}, at(20.0)));
}

TEST(SurfaceMemory, AlignmentJitterAtAStandstillDrivesNoPath) {
  SurfaceMemory memory = memoryOfAPaneThatDrifts();
  // 2,000 frames, each origin 2 cm from the last (alternating): 40 m of
  // steps, but the sensor stands still.
  for (int k = 0; k < 2000; ++k) memory.forget({k % 2 ? 0.02 : 0.0, 0.0}, at(1.0 + k * 0.01));
  EXPECT_TRUE(memory.liesBeyondASurface(kOrigin, {0.0, 1.6}, at(21.0)));
}

}  // namespace
}  // namespace scanfilter
