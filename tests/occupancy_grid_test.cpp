#include <cstdio>
#include <filesystem>
#include <memory>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "scan_builder.hpp"
#include "scanfilter/map_files.hpp"
#include "scanfilter/occupancy_grid.hpp"
#include "scanfilter/point_code.hpp"

namespace scanfilter {
namespace {

using test::castScan;
using test::World;

// Walls in the middle of 5 cm cells, so no return sits on a cell boundary.
const World kRoom =
    World{}.wall({3.02, -3.02}, {3.02, 3.02}).wall({-3.02, -3.02}, {3.02, -3.02}).wall({-3.02, 3.02}, {3.02, 3.02}).wall({-3.02, -3.02}, {-3.02, 3.02});

// Integrates frames first..last-1 of a slow drive through the room.
void feed(OccupancyGrid& grid, int first, int last) {
  const SensorInfo sensor = test::simpleSensor();
  for (int k = first; k < last; ++k) grid.integrate(castScan(kRoom, {0.02 * k, 0.01 * k, 0.0}, sensor), sensor, {});
}

std::unique_ptr<OccupancyGrid> mapOf(int first, int last) {
  auto grid = std::make_unique<OccupancyGrid>(OccupancyGridParams{});
  feed(*grid, first, last);
  return grid;
}

TEST(OccupancyGrid, WallsOccupiedFreeSpaceFreeBeyondUnknown) {
  const auto map = mapOf(0, 10);
  const OccupancyGrid& grid = *map;
  EXPECT_GE(grid.rosValue(grid.cellOf({3.02, 0.5})), 65) << "the wall at x = 3.02";
  EXPECT_EQ(grid.rosValue(grid.cellOf({1.5, 0.5})), 12) << "free space, clamped at 0.12";
  EXPECT_EQ(grid.rosValue(grid.cellOf({4.0, 0.5})), -1) << "behind the wall: never seen";
  EXPECT_EQ(grid.scansIntegrated(), 10u);
}

TEST(OccupancyGrid, RemovedPointsUpdateNothing) {
  const SensorInfo sensor = test::simpleSensor();
  OccupancyGrid grid{OccupancyGridParams{}};
  const Scan scan = castScan(kRoom, {}, sensor);
  std::vector<std::uint8_t> labels(scan.size(), static_cast<std::uint8_t>(PointCode::kJump));
  grid.integrate(scan, sensor, labels);
  EXPECT_TRUE(grid.bounds().empty());
}

TEST(OccupancyGrid, MemoryFollowsTheAreaSeen) {
  // A 1,000 m² building at 5 cm: 400,000 cells; its tiles stay far below 100 MB.
  OccupancyGrid grid{OccupancyGridParams{}};
  for (double x = 0; x < 32; x += 0.05)
    for (double y = 0; y < 32; y += 1.0) grid.setLogOdds(grid.cellOf({x, y}), 1.0f);
  EXPECT_LT(grid.memoryBytes(), 100u * 1000 * 1000);
  EXPECT_LE(grid.tileCount(), 12u * 12u);
}

TEST(MapFiles, SaveLoadContinueEqualsOneGo) {
  const std::string base = (std::filesystem::path(::testing::TempDir()) / "continued").string();
  const auto whole = mapOf(0, 20);
  saveMap(*mapOf(0, 10), base);
  OccupancyGrid continued{OccupancyGridParams{}};
  loadMapState(continued, base);
  feed(continued, 10, 20);
  const CellBox box = whole->bounds();
  ASSERT_FALSE(box.empty());
  for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
    for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x)
      ASSERT_EQ(whole->logOdds({x, y}), continued.logOdds({x, y})) << x << ", " << y;
}

// The note travels inside BASE.logodds (one rename with the state it describes).
TEST(MapFiles, NoteSavedWithTheState) {
  const std::string base = (std::filesystem::path(::testing::TempDir()) / "noted").string();
  saveMap(*mapOf(0, 10), base, "scans_integrated: 10\nlast_sequence: 9\n");
  OccupancyGrid loaded{OccupancyGridParams{}};
  EXPECT_EQ(loadMapState(loaded, base), "scans_integrated: 10\nlast_sequence: 9\n");
  saveMap(*mapOf(0, 10), base);
  EXPECT_EQ(loadMapState(loaded, base), "");
}

// Reads the saved PGM and YAML back with a parser of its own, not the writer's code.
TEST(MapFiles, PgmAndYamlReadBack) {
  const std::string base = (std::filesystem::path(::testing::TempDir()) / "room").string();
  const auto map = mapOf(0, 10);
  const OccupancyGrid& grid = *map;
  saveMap(grid, base);
  std::ifstream pgm(base + ".pgm", std::ios::binary);
  std::string magic, comment;
  int width = 0, height = 0, maxval = 0;
  pgm >> magic;
  pgm.ignore();
  std::getline(pgm, comment);
  pgm >> width >> height >> maxval;
  pgm.ignore();
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height);
  pgm.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
  ASSERT_TRUE(pgm) << "truncated PGM";
  EXPECT_EQ(magic, "P5");
  EXPECT_EQ(maxval, 255);
  EXPECT_EQ(width, grid.bounds().width());
  EXPECT_EQ(height, grid.bounds().height());

  std::ifstream yaml(base + ".yaml");
  std::stringstream text;
  text << yaml.rdbuf();
  EXPECT_NE(text.str().find("image: room.pgm"), std::string::npos);
  EXPECT_NE(text.str().find("resolution: 0.05"), std::string::npos);
  EXPECT_NE(text.str().find("negate: 0"), std::string::npos);
  double ox = 0, oy = 0;
  const auto at = text.str().find("origin: [");
  ASSERT_NE(at, std::string::npos);
  std::sscanf(text.str().c_str() + at, "origin: [%lf, %lf", &ox, &oy);
  // The pixel of a wall point, found from the YAML origin alone: black.
  const auto pixel = [&](double x, double y) {
    const int col = static_cast<int>((x - ox) / 0.05), row = height - 1 - static_cast<int>((y - oy) / 0.05);
    return pixels[static_cast<std::size_t>(row) * width + col];
  };
  EXPECT_EQ(pixel(3.02, 0.5), 0);
  EXPECT_EQ(pixel(1.5, 0.5), 254);
  EXPECT_TRUE(std::filesystem::exists(base + ".png"));
  EXPECT_FALSE(std::filesystem::exists(base + ".pgm.tmp")) << "written then renamed";
}

}  // namespace
}  // namespace scanfilter
