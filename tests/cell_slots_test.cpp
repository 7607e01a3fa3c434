// CellSlots and the obstacle window built on it: a reset clears what the
// last frame set, so a rectangle rebuilt smaller, larger or elsewhere holds
// exactly its own frame's cells.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include <gtest/gtest.h>

#include "scanfilter/cell_slots.hpp"
#include "scanfilter/obstacle_window.hpp"
#include "scanfilter/penetration_grid.hpp"

namespace scanfilter {
namespace {

void expectAllNone(const CellSlots& slots, std::size_t cells) {
  for (std::size_t i = 0; i < cells; ++i) ASSERT_EQ(slots[i], CellSlots::kNone) << "offset " << i;
}

TEST(CellSlots, ResetClearsWhatWasSetWhateverTheNextSize) {
  CellSlots slots;
  slots.reset(100);
  expectAllNone(slots, 100);
  slots.set(3, 0);
  slots.set(99, 1);
  EXPECT_EQ(slots[3], 0);
  EXPECT_EQ(slots[99], 1);
  slots.reset(50);  // smaller: offset 99 lies beyond it, and must not come back later
  expectAllNone(slots, 50);
  slots.set(49, 7);
  slots.reset(200);  // larger than ever before
  expectAllNone(slots, 200);
}

// Obstacles of a grid as the window sees them over lo..hi, against the grid.
void expectWindowMatchesGrid(const ObstacleWindow& window, const PenetrationGrid& grid, CellIndex lo,
                             CellIndex hi) {
  for (std::int32_t y = lo.y; y <= hi.y; ++y)
    for (std::int32_t x = lo.x; x <= hi.x; ++x)
      ASSERT_EQ(window.isObstacle({x, y}), grid.count({x, y}) > 0) << "cell " << x << ", " << y;
}

TEST(ObstacleWindow, ARebuiltWindowHoldsOnlyItsOwnFramesObstacles) {
  PenetrationGrid grid(0.05, 0);  // every counted cell is an obstacle
  for (int k = 0; k < 40; ++k) grid.add(Eigen::Vector2d(0.05 * k + 0.01, 0.5));  // a wall along y = 0.5
  ObstacleWindow window;
  const auto at = [](CellIndex c) { return Eigen::Vector2d(c.x, c.y); };  // positions are not what this tests
  window.build(grid, {-5, -5}, {60, 30}, at);
  expectWindowMatchesGrid(window, grid, {-5, -5}, {60, 30});

  // The wall moves (the next frame's cache), the window shrinks and shifts:
  // none of the first frame's cells may linger.
  PenetrationGrid moved(0.05, 0);
  for (int k = 0; k < 10; ++k) moved.add(Eigen::Vector2d(0.21, 0.05 * k + 0.01));  // a wall along x = 0.21
  window.build(moved, {0, 0}, {20, 20}, at);
  expectWindowMatchesGrid(window, moved, {-3, -3}, {23, 23});
  window.build(moved, {-10, -10}, {80, 40}, at);  // and larger than the first
  expectWindowMatchesGrid(window, moved, {-10, -10}, {80, 40});
}

TEST(ObstacleWindow, AnErasedCellIsNoLongerMetByAWalkAlongEitherAxis) {
  PenetrationGrid grid(0.05, 0);
  for (int k = 0; k < 3; ++k) {
    grid.add(Eigen::Vector2d(1.0 + 0.05 * k + 0.025, 0.025));  // cells (20..22, 0): a walk along x
    grid.add(Eigen::Vector2d(0.025, 1.0 + 0.05 * k + 0.025));  // cells (0, 20..22): a walk along y
  }
  ObstacleWindow window;
  window.build(grid, {-5, -5}, {40, 40}, [&grid](CellIndex c) { return grid.cellCentre(c); });
  // The cells a walk from the origin's cell to `to` meets, by their index along it.
  const auto met = [&window](const Eigen::Vector2d& to, bool along_x) {
    std::vector<std::int32_t> found;
    window.anyAlongRay(Eigen::Vector2d(0.025, 0.025), to, 0.01, [&](CellIndex c, const Eigen::Vector2d&) {
      found.push_back(along_x ? c.x : c.y);
      return false;
    });
    return found;
  };
  const Eigen::Vector2d along_x(1.9, 0.025), along_y(0.025, 1.9);
  EXPECT_EQ(met(along_x, true), (std::vector<std::int32_t>{20, 21, 22}));
  EXPECT_EQ(met(along_y, false), (std::vector<std::int32_t>{20, 21, 22}));
  window.erase({21, 0});
  window.erase({0, 22});
  window.erase({30, 0});  // not an obstacle: nothing happens
  window.erase({90, 0});  // outside the window: nothing happens
  EXPECT_FALSE(window.isObstacle({21, 0}));
  EXPECT_TRUE(window.isObstacle({20, 0}));
  EXPECT_EQ(met(along_x, true), (std::vector<std::int32_t>{20, 22}));
  EXPECT_EQ(met(along_y, false), (std::vector<std::int32_t>{20, 21}));
  // Rebuilt, the window holds the grid's cells again, the erased ones too.
  window.build(grid, {-5, -5}, {40, 40}, [&grid](CellIndex c) { return grid.cellCentre(c); });
  expectWindowMatchesGrid(window, grid, {-5, -5}, {40, 40});
}

}  // namespace
}  // namespace scanfilter
