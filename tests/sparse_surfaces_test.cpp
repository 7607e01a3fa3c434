// sparseSurfaces: which lines of thinly filled cells make a surface.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "scanfilter/floor_to_int.hpp"
#include "scanfilter/sparse_surfaces.hpp"

namespace scanfilter {
namespace {

constexpr double kCell = 0.05;

CellMean sparseCellAt(Eigen::Vector2d at) {
  return {{floorToInt(at.x() / kCell), floorToInt(at.y() / kCell)}, at, true};
}

// The cell means of a pane along y = `y` from x0 to x1: one return in every
// cell it crosses, `jitter` m off the line (σ), none in the cells listed as
// holes (counted from x0).
std::vector<CellMean> pane(double x0, double x1, double y, double jitter = 0.004, std::vector<int> holes = {}) {
  std::vector<CellMean> cells;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, jitter);
  const int n = static_cast<int>(std::lround((x1 - x0) / kCell));
  for (int k = 0; k < n; ++k) {
    if (std::find(holes.begin(), holes.end(), k) != holes.end()) continue;
    // Inside its cell whatever the jitter: the cell is the one it falls in.
    cells.push_back(sparseCellAt({x0 + (k + 0.5) * kCell, y + noise(rng)}));
  }
  return cells;
}

bool spans(const StraightSegment& s, Eigen::Vector2d from, Eigen::Vector2d to, double tolerance) {
  const bool forward = (s.a - from).norm() < tolerance && (s.b - to).norm() < tolerance;
  const bool backward = (s.a - to).norm() < tolerance && (s.b - from).norm() < tolerance;
  return forward || backward;
}

std::vector<StraightSegment> surfacesOf(const std::vector<CellMean>& cells,
                                        const SparseSurfaceParams& params = SparseSurfaceParams{}) {
  return sparseSurfaces(cells, kCell, params);
}

TEST(SparseSurfaces, APaneWithOneReturnACellIsOneSurfaceEndToEnd) {
  const auto found = surfacesOf(pane(0.0, 2.0, 1.0));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(spans(found[0], {0.025, 1.0}, {1.975, 1.0}, 0.02));
}

TEST(SparseSurfaces, HolesNarrowerThanMaxGapAreBridgedAWiderGapSplits) {
  // Holes of 3 cells (0.15 m, a pane that returned nothing there) are bridged.
  EXPECT_EQ(surfacesOf(pane(0.0, 2.0, 1.0, 0.004, {5, 6, 7, 20, 21, 22})).size(), 1u);
  // A 0.9 m doorway (18 cells) splits it in two.
  std::vector<int> doorway;
  for (int k = 10; k < 28; ++k) doorway.push_back(k);
  EXPECT_EQ(surfacesOf(pane(0.0, 2.0, 1.0, 0.004, doorway)).size(), 2u);
}

TEST(SparseSurfaces, ScatteredCellsMakeNone) {
  std::map<std::pair<int, int>, CellMean> distinct;  // one mean a cell, as the grid gives
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> where(0.0, 3.0);
  for (int k = 0; k < 300; ++k) {
    const CellMean c = sparseCellAt({where(rng), where(rng)});
    distinct.emplace(std::pair{c.cell.x, c.cell.y}, c);
  }
  std::vector<CellMean> cells;
  for (const auto& [key, c] : distinct) cells.push_back(c);
  EXPECT_TRUE(surfacesOf(cells).empty());
}

TEST(SparseSurfaces, AThickBandIsNoSurface) {
  // A wall seen at grazing incidence from afar: its returns spread over
  // three rows of cells across it.
  std::vector<CellMean> band;
  for (const double y : {0.975, 1.025, 1.075}) {
    const auto row = pane(0.0, 2.0, y);
    band.insert(band.end(), row.begin(), row.end());
  }
  EXPECT_TRUE(surfacesOf(band).empty());
}

// The cells of `cells`, each with the range noise `sigma` where it lies.
std::vector<CellMean> withRangeNoise(std::vector<CellMean> cells, double sigma) {
  for (CellMean& c : cells) c.range_noise = sigma;
  return cells;
}

// How much of a line the surfaces found cover, in metres.
double lengthFound(const std::vector<StraightSegment>& found) {
  double length = 0.0;
  for (const StraightSegment& s : found) length += (s.b - s.a).norm();
  return length;
}

// A triangulation scanner's pane at 4 m: its returns scatter 2 cm (σ)
// across the line, thicker than max_thickness, but no more than the range
// noise there. With a quiet sensor's limits only stretches of it that
// happen to lie thinly pass (under a third of its 2 m); with the limits the
// noise widens, nearly all of it is one surface.
TEST(SparseSurfaces, ANoisySensorsPaneIsASurfaceWhereItsRangeNoiseIsThatLarge) {
  constexpr double kSigma = 0.02;
  const auto noisy_pane = pane(0.0, 2.0, 1.0, kSigma);
  EXPECT_LT(lengthFound(surfacesOf(noisy_pane)), 0.7);  // no noise measured
  const auto found = surfacesOf(withRangeNoise(noisy_pane, kSigma));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_GT(lengthFound(found), 1.8);
  SparseSurfaceParams not_widened;
  not_widened.max_thickness_noise_sigmas = 0.0;
  not_widened.max_deviation_noise_sigmas = 0.0;
  EXPECT_LT(lengthFound(surfacesOf(withRangeNoise(noisy_pane, kSigma), not_widened)), 0.7);
}

// However noisy the sensor, the limits stop at their ceilings: three rows
// of cells 5 cm apart (a wall at grazing incidence) stay no surface.
TEST(SparseSurfaces, TheRangeNoiseWidensTheLimitsNoFartherThanTheirCeilings) {
  std::vector<CellMean> band;
  for (const double y : {0.975, 1.025, 1.075}) {
    const auto row = pane(0.0, 2.0, y);
    band.insert(band.end(), row.begin(), row.end());
  }
  EXPECT_TRUE(surfacesOf(withRangeNoise(band, 0.2)).empty());
  SparseSurfaceParams no_ceiling;
  no_ceiling.max_thickness_ceiling = 1.0;
  no_ceiling.max_deviation_ceiling = 1.0;
  EXPECT_FALSE(surfacesOf(withRangeNoise(band, 0.2), no_ceiling).empty());  // what the ceilings prevent
  SparseSurfaceParams at_the_floor;  // ceilings at the limits themselves: the noise widens nothing
  at_the_floor.max_thickness_ceiling = at_the_floor.max_thickness;
  at_the_floor.max_deviation_ceiling = at_the_floor.max_deviation;
  EXPECT_LT(lengthFound(surfacesOf(withRangeNoise(pane(0.0, 2.0, 1.0, 0.02), 0.02), at_the_floor)), 0.7);
}

// Each cell's own noise decides its limits: a noisy pane whose noise was
// measured only along its first half is found along about that half.
TEST(SparseSurfaces, EachCellsLimitsFollowItsOwnRangeNoise) {
  auto cells = pane(0.0, 2.0, 1.0, 0.02);
  for (CellMean& c : cells) c.range_noise = c.at.x() < 1.0 ? 0.02 : 0.0;
  const double half = lengthFound(surfacesOf(cells));
  EXPECT_GT(half, 0.8);
  EXPECT_LT(half, 1.5);
}

// A noise that is no number (NaN, infinite) widens nothing: the limits as
// configured, as for noise not measured.
TEST(SparseSurfaces, ANoiseThatIsNoNumberWidensNothing) {
  const auto noisy_pane = pane(0.0, 2.0, 1.0, 0.02);
  const double quiet = lengthFound(surfacesOf(noisy_pane));
  EXPECT_EQ(lengthFound(surfacesOf(withRangeNoise(noisy_pane, std::numeric_limits<double>::quiet_NaN()))), quiet);
  EXPECT_EQ(lengthFound(surfacesOf(withRangeNoise(noisy_pane, std::numeric_limits<double>::infinity()))), quiet);
}

// A thin pane with one cell 4 cm off its line. A quiet sensor's local
// lines leave that cell out, and the rest is one surface. With 2 cm of
// noise the cell joins (its widened thickness lets it), and the fit keeps
// it within 4 σ (8 cm); with the deviation's ceiling at 3 cm the fit
// refuses the group it joined.
TEST(SparseSurfaces, TheDeviationCeilingBoundsHowFarOffItsLineACellMayLie) {
  auto cells = pane(0.0, 2.0, 1.0);
  cells[20].at.y() = 1.04;
  cells[20].cell.y = floorToInt(1.04 / kCell);
  EXPECT_EQ(surfacesOf(cells).size(), 1u);
  EXPECT_EQ(surfacesOf(withRangeNoise(cells, 0.02)).size(), 1u);
  SparseSurfaceParams low_ceiling;
  low_ceiling.max_deviation_ceiling = 0.03;
  EXPECT_TRUE(surfacesOf(withRangeNoise(cells, 0.02), low_ceiling).empty());
}

TEST(SparseSurfaces, TooShortOrTooFewCellsIsNoSurface) {
  // Six cells over 0.25 m: enough cells, too short; long enough at 0.2 m.
  EXPECT_TRUE(surfacesOf(pane(0.0, 0.30, 1.0)).empty());
  SparseSurfaceParams shorter;
  shorter.min_length = 0.2;
  EXPECT_EQ(surfacesOf(pane(0.0, 0.30, 1.0), shorter).size(), 1u);
  SparseSurfaceParams need_more;
  need_more.min_cells = 50;
  EXPECT_TRUE(surfacesOf(pane(0.0, 2.0, 1.0), need_more).empty());  // 40 cells
}

TEST(SparseSurfaces, OnlySparseCellsMakeASurfaceObstaclesStillCountAsNeighbours) {
  // A wall whose cells are all obstacles is the cache's own business.
  std::vector<CellMean> wall = pane(0.0, 2.0, 1.0);
  for (CellMean& c : wall) c.sparse = false;
  EXPECT_TRUE(surfacesOf(wall).empty());
  // Every other cell an obstacle (a pane seen head-on in places): still a
  // surface, from the sparse ones, with the obstacles as their neighbours.
  std::vector<CellMean> mixed = pane(0.0, 2.0, 1.0);
  for (std::size_t k = 0; k < mixed.size(); k += 2) mixed[k].sparse = false;
  EXPECT_EQ(surfacesOf(mixed).size(), 1u);
}

TEST(SparseSurfaces, ACurveIsNoSurface) {
  // A bend of 0.2 m over 2 m: each cell's neighbourhood is thin, but the
  // whole lies farther than max_deviation off its fitted line.
  std::vector<CellMean> arc;
  for (int k = 0; k < 40; ++k) {
    const double x = (k + 0.5) * kCell, u = x - 1.0;
    arc.push_back(sparseCellAt({x, 1.0 + 0.2 * (1.0 - u * u)}));
  }
  EXPECT_TRUE(surfacesOf(arc).empty());
}

TEST(SparseSurfaces, CrossingPanesAreNotJoinedAcrossTheirAngle) {
  std::vector<CellMean> cells = pane(0.0, 2.0, 1.0);
  for (int k = 0; k < 40; ++k) {
    if (k == 20) continue;  // the crossing cell is the horizontal pane's
    cells.push_back(sparseCellAt({1.0 + 0.002 * (k % 2), (k + 0.5) * kCell}));
  }
  const auto found = surfacesOf(cells);
  ASSERT_FALSE(found.empty());
  for (const StraightSegment& s : found) {
    const Eigen::Vector2d d = (s.b - s.a).normalized();
    EXPECT_GT(std::max(std::abs(d.x()), std::abs(d.y())), 0.99) << "every surface along one pane or the other";
  }
}

TEST(SparseSurfaces, TwoPanesApartAreTwoSurfaces) {
  std::vector<CellMean> cells = pane(0.0, 2.0, 1.0);
  for (int k = 0; k < 40; ++k) cells.push_back(sparseCellAt({3.0 + 0.002 * (k % 2), (k + 0.5) * kCell}));
  EXPECT_EQ(surfacesOf(cells).size(), 2u);
}

TEST(SparseSurfaces, NoCellsOrNoFiniteCellsNoSurface) {
  EXPECT_TRUE(sparseSurfaces({}, kCell, SparseSurfaceParams{}).empty());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<CellMean> cells = pane(0.0, 2.0, 1.0);
  cells.push_back({{5, 5}, {nan, nan}, true});
  EXPECT_EQ(surfacesOf(cells).size(), 1u) << "a cell without a finite mean is left out";
}

}  // namespace
}  // namespace scanfilter
