// The misdetected-error breakdown's record of when surfaces were seen
// (bench/surface_history.hpp): a window counts the hits before its end and
// not before its start, in the point's cell and its eight neighbours.
#include "surface_history.hpp"

#include <gtest/gtest.h>

namespace scanfilter::bench {
namespace {

constexpr double kCell = 0.05;

TEST(SurfaceHistoryTest, AWindowCountsTheHitsFromItsStartUpToItsEnd) {
  SurfaceHistory history(kCell);
  const Eigen::Vector2d p(1.01, 2.01);
  for (double t : {0.0, 1.0, 2.0}) history.add(p, t);
  EXPECT_EQ(history.mostHitsNear(p, 3.0, 3.0), 3);  // [0, 3)
  EXPECT_EQ(history.mostHitsNear(p, 3.0, 1.5), 1);  // [1.5, 3): only t = 2
  EXPECT_EQ(history.mostHitsNear(p, 2.0, 2.0), 2);  // [0, 2): a hit at the end is not before it
  EXPECT_EQ(history.mostHitsNear(p, 0.0, 10.0), 0);
}

TEST(SurfaceHistoryTest, TheNeighbouringCellsCountButNotTogether) {
  SurfaceHistory history(kCell);
  const Eigen::Vector2d p(1.01, 2.01);
  history.add(p + Eigen::Vector2d(kCell, 0.0), 0.0);  // the cell to the right, once
  for (double t : {0.0, 0.5}) history.add(p + Eigen::Vector2d(-kCell, -kCell), t);  // below left, twice
  // The most in any one cell, not the sum over the nine.
  EXPECT_EQ(history.mostHitsNear(p, 1.0, 1.0), 2);
  // From beside the right-hand cell it is near; from two cells past it, not.
  EXPECT_EQ(history.mostHitsNear(p + Eigen::Vector2d(2 * kCell, 0.0), 1.0, 1.0), 1);
  EXPECT_EQ(history.mostHitsNear(p + Eigen::Vector2d(3 * kCell, 0.0), 1.0, 1.0), 0);
}

TEST(SurfaceHistoryTest, NegativeCoordinatesFallInTheirOwnCells) {
  SurfaceHistory history(kCell);
  history.add({-0.01, -0.01}, 0.0);  // cell (-1, -1)
  EXPECT_EQ(history.mostHitsNear({0.07, 0.07}, 1.0, 1.0), 0);   // cell (1, 1): two away
  EXPECT_EQ(history.mostHitsNear({0.02, 0.02}, 1.0, 1.0), 1);   // cell (0, 0): beside it
}

}  // namespace
}  // namespace scanfilter::bench
