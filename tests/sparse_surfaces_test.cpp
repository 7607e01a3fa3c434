// sparseSurfaces: which lines of thinly filled cells make a surface.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "scanfilter/sparse_surfaces.hpp"

namespace scanfilter {
namespace {

constexpr double kCell = 0.05;

// The cell means of a pane along y = `y` from x0 to x1: one return in every
// cell it crosses, `jitter` m off the line, none in the cells listed as holes.
std::vector<CellMean> pane(double x0, double x1, double y, double jitter = 0.004, std::vector<int> holes = {}) {
  std::vector<CellMean> cells;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, jitter);
  const int n = static_cast<int>(std::lround((x1 - x0) / kCell));
  for (int k = 0; k < n; ++k) {
    if (std::find(holes.begin(), holes.end(), k) != holes.end()) continue;
    cells.push_back({{x0 + (k + 0.5) * kCell, y + noise(rng)}, true});
  }
  return cells;
}

bool spans(const StraightSegment& s, Eigen::Vector2d from, Eigen::Vector2d to, double tolerance) {
  const bool forward = (s.a - from).norm() < tolerance && (s.b - to).norm() < tolerance;
  const bool backward = (s.a - to).norm() < tolerance && (s.b - from).norm() < tolerance;
  return forward || backward;
}

TEST(SparseSurfaces, APaneWithOneReturnACellIsOneSurfaceEndToEnd) {
  const auto found = sparseSurfaces(pane(0.0, 2.0, 1.0), kCell, SparseSurfaceParams{});
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(spans(found[0], {0.025, 1.0}, {1.975, 1.0}, 0.02));
}

TEST(SparseSurfaces, HolesNarrowerThanMaxGapAreBridgedAWiderGapSplits) {
  // Holes of 3 cells (0.15 m, a pane that returned nothing there) are bridged.
  const auto holed = sparseSurfaces(pane(0.0, 2.0, 1.0, 0.004, {5, 6, 7, 20, 21, 22}), kCell, SparseSurfaceParams{});
  ASSERT_EQ(holed.size(), 1u);
  // A 0.9 m doorway (18 cells) splits it in two.
  std::vector<int> doorway;
  for (int k = 10; k < 28; ++k) doorway.push_back(k);
  const auto split = sparseSurfaces(pane(0.0, 2.0, 1.0, 0.004, doorway), kCell, SparseSurfaceParams{});
  ASSERT_EQ(split.size(), 2u);
}

TEST(SparseSurfaces, ScatteredCellsMakeNone) {
  std::vector<CellMean> cells;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> where(0.0, 3.0);
  for (int k = 0; k < 300; ++k) cells.push_back({{where(rng), where(rng)}, true});
  EXPECT_TRUE(sparseSurfaces(cells, kCell, SparseSurfaceParams{}).empty());
}

TEST(SparseSurfaces, AThickBandIsNoSurface) {
  // A wall seen at grazing incidence from afar: its returns spread over
  // three rows of cells across it.
  std::vector<CellMean> band;
  for (const double y : {0.975, 1.025, 1.075}) {
    const auto row = pane(0.0, 2.0, y);
    band.insert(band.end(), row.begin(), row.end());
  }
  EXPECT_TRUE(sparseSurfaces(band, kCell, SparseSurfaceParams{}).empty());
}

TEST(SparseSurfaces, TooShortOrTooFewCellsIsNoSurface) {
  EXPECT_TRUE(sparseSurfaces(pane(0.0, 0.25, 1.0), kCell, SparseSurfaceParams{}).empty());  // 5 cells, 0.2 m
  SparseSurfaceParams need_more;
  need_more.min_cells = 50;
  EXPECT_TRUE(sparseSurfaces(pane(0.0, 2.0, 1.0), kCell, need_more).empty());  // 40 cells
}

TEST(SparseSurfaces, OnlySparseCellsMakeASurfaceObstaclesStillCountAsNeighbours) {
  // A wall whose cells are all obstacles is the cache's own business.
  std::vector<CellMean> wall = pane(0.0, 2.0, 1.0);
  for (CellMean& c : wall) c.sparse = false;
  EXPECT_TRUE(sparseSurfaces(wall, kCell, SparseSurfaceParams{}).empty());
  // Every other cell an obstacle (a pane seen head-on in places): still a
  // surface, from the sparse ones, with the obstacles as their neighbours.
  std::vector<CellMean> mixed = pane(0.0, 2.0, 1.0);
  for (std::size_t k = 0; k < mixed.size(); k += 2) mixed[k].sparse = false;
  EXPECT_EQ(sparseSurfaces(mixed, kCell, SparseSurfaceParams{}).size(), 1u);
}

TEST(SparseSurfaces, TwoPanesApartAreTwoSurfaces) {
  std::vector<CellMean> cells = pane(0.0, 2.0, 1.0);
  // A vertical pane x = 3 (beside the first, not touching it).
  for (int k = 0; k < 40; ++k) cells.push_back({{3.0 + 0.002 * (k % 2), (k + 0.5) * kCell}, true});
  EXPECT_EQ(sparseSurfaces(cells, kCell, SparseSurfaceParams{}).size(), 2u);
}

TEST(SparseSurfaces, NoCellsNoSurface) { EXPECT_TRUE(sparseSurfaces({}, kCell, SparseSurfaceParams{}).empty()); }

}  // namespace
}  // namespace scanfilter
