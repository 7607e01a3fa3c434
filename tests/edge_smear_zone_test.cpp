// EdgeSmearZone: which surface ends lie within the radius of a point, found
// by bucket, against every end in turn.
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "scanfilter/edge_smear_zone.hpp"

namespace scanfilter {
namespace {

std::vector<Eigen::Vector2d> endsNear(const EdgeSmearZone& zone, const Eigen::Vector2d& q) {
  std::vector<Eigen::Vector2d> found;
  zone.anyEndNear(q, [&found](const Eigen::Vector2d& end) {
    found.push_back(end);
    return false;  // all of them
  });
  return found;
}

TEST(EdgeSmearZone, FindsEveryEndWithinTheRadiusAndNoOther) {
  // Ends on both sides of the axes (negative buckets), points anywhere near.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  std::vector<Eigen::Vector2d> ends;
  for (int k = 0; k < 300; ++k) ends.emplace_back(coordinate(rng), coordinate(rng));
  const double radius = 0.15;
  EdgeSmearZone zone;
  zone.build(ends, radius);
  for (int trial = 0; trial < 2000; ++trial) {
    const Eigen::Vector2d q(coordinate(rng), coordinate(rng));
    std::size_t expected = 0;
    for (const auto& e : ends) expected += (e - q).squaredNorm() <= radius * radius;
    EXPECT_EQ(endsNear(zone, q).size(), expected) << "at " << q.transpose();
  }
}

TEST(EdgeSmearZone, AnEndExactlyOnTheCircleCountsAndTheSearchStopsWhenAsked) {
  EdgeSmearZone zone;
  const std::vector<Eigen::Vector2d> ends{{0.25, 0.0}, {0.0, 0.0}};
  zone.build(ends, 0.25);
  EXPECT_EQ(endsNear(zone, {0.0, 0.0}).size(), 2u) << "(0.25, 0) lies on the circle";
  int calls = 0;
  EXPECT_TRUE(zone.anyEndNear({0.0, 0.0}, [&calls](const Eigen::Vector2d&) { return ++calls == 1; }));
  EXPECT_EQ(calls, 1);
  EXPECT_FALSE(zone.anyEndNear({1.0, 1.0}, [](const Eigen::Vector2d&) { return true; }));
}

TEST(EdgeSmearZone, NoRadiusOrNoFiniteEndsMakeAnEmptyZone) {
  EdgeSmearZone zone;
  const std::vector<Eigen::Vector2d> ends{{0.0, 0.0}};
  zone.build(ends, 0.0);
  EXPECT_TRUE(zone.empty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Eigen::Vector2d> no_returns{{nan, nan}};
  zone.build(no_returns, 0.1);
  EXPECT_TRUE(zone.empty());
  zone.build(ends, 0.1);
  EXPECT_FALSE(zone.empty());
  EXPECT_TRUE(endsNear(zone, {nan, 0.0}).empty()) << "a NaN point is near nothing";
}

}  // namespace
}  // namespace scanfilter
