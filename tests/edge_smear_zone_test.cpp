// EdgeSmearZone: whether a surface end lies within the radius of a point,
// found by bucket, against every end in turn.
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "scanfilter/edge_smear_zone.hpp"

namespace scanfilter {
namespace {

TEST(EdgeSmearZone, HoldsAPointExactlyWhenAnEndLiesWithinTheRadius) {
  // Ends on both sides of the axes (negative buckets), points anywhere near.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  std::vector<Eigen::Vector2d> ends;
  for (int k = 0; k < 300; ++k) ends.emplace_back(coordinate(rng), coordinate(rng));
  const double radius = 0.15;
  EdgeSmearZone zone;
  zone.build(ends, radius);
  int inside = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Eigen::Vector2d q(coordinate(rng), coordinate(rng));
    bool expected = false;
    for (const auto& e : ends) expected = expected || (e - q).squaredNorm() <= radius * radius;
    inside += expected;
    EXPECT_EQ(zone.contains(q), expected) << "at " << q.transpose();
  }
  EXPECT_GT(inside, 400) << "both answers must occur";
}

TEST(EdgeSmearZone, AnEndExactlyOnTheCircleCounts) {
  EdgeSmearZone zone;
  const std::vector<Eigen::Vector2d> ends{{0.25, 0.0}};
  zone.build(ends, 0.25);
  EXPECT_TRUE(zone.contains({0.0, 0.0}));
  EXPECT_FALSE(zone.contains({-0.001, 0.0}));
}

TEST(EdgeSmearZone, NoRadiusNoFiniteEndsOrAFarPointContainNothing) {
  EdgeSmearZone zone;
  const std::vector<Eigen::Vector2d> ends{{0.0, 0.0}};
  zone.build(ends, 0.0);
  EXPECT_FALSE(zone.contains({0.0, 0.0}));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector2d> no_returns{{nan, nan}};
  zone.build(no_returns, 0.1);
  EXPECT_FALSE(zone.contains({0.0, 0.0}));
  zone.build(ends, 0.1);
  EXPECT_TRUE(zone.contains({0.05, 0.05}));
  EXPECT_FALSE(zone.contains({nan, 0.0})) << "a NaN point is near nothing";
  EXPECT_FALSE(zone.contains({1e300, -1e300})) << "bucket coordinates saturate, they do not overflow";
  zone.build(ends, 1e-300);  // a radius that small must not overflow either
  EXPECT_TRUE(zone.contains({0.0, 0.0}));
  EXPECT_FALSE(zone.contains({1.0, 0.0}));
}

}  // namespace
}  // namespace scanfilter
