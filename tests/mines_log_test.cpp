#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "scanfilter/input_error.hpp"
#include "scanfilter/mines_log_reader.hpp"
#include "scanfilter/scan_source.hpp"
#include "temp_file.hpp"

namespace scanfilter {
namespace {

using test::TempFile;

// One log line: time, an unknown field, the wheel ticks, 20 state fields
// (one of them decimal, as in the real files), 682 ranges, the dropped extra.
std::string minesLine(long long micros, long long left, long long right, int range_mm, int first_range_mm = -1) {
  std::string line = std::to_string(micros) + " 14554 " + std::to_string(left) + " " + std::to_string(right);
  for (int i = 4; i < 24; ++i) line += i == 7 ? " 167.2" : " 0";
  for (int i = 0; i < 682; ++i) line += " " + std::to_string(i == 0 && first_range_mm >= 0 ? first_range_mm : range_mm);
  return line + " 0\n";
}

TEST(MinesLog, ReadsRangesAnglesAndTime) {
  TempFile file("a.dat", minesLine(1'000'000, 0, 0, 1500, 12) + minesLine(1'100'000, 0, 0, 0));
  auto source = openScanSource(file.path());
  const SensorInfo& sensor = source->header().sensor;
  EXPECT_EQ(sensor.direction, BeamDirection::kCcw);
  EXPECT_DOUBLE_EQ(sensor.mount.x, 0.145);
  ScanRecord r;
  ASSERT_TRUE(source->next(r));
  EXPECT_EQ(r.line, 1u);
  EXPECT_EQ(r.scan.stamp.toDecimal(), "1");
  ASSERT_EQ(r.scan.size(), 682u);
  EXPECT_TRUE(std::isnan(r.scan.ranges[0])) << "12 mm is a URG error code, not a return";
  EXPECT_DOUBLE_EQ(r.scan.ranges[1], 1.5);
  EXPECT_NEAR(r.scan.angle_min, -120.0 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_NEAR(r.scan.angle_min + 681 * r.scan.angle_increment, 120.0 * std::numbers::pi / 180.0, 1e-12);
  ASSERT_TRUE(source->next(r));
  EXPECT_TRUE(std::isnan(r.scan.ranges[5])) << "0 is no return";
  EXPECT_FALSE(source->next(r));
}

TEST(MinesLog, DeadReckonsPosesFromWheelTicks) {
  const double wheel_turn = 2.0 * std::numbers::pi * 0.077;  // m per 2000 ticks
  TempFile file("b.dat", minesLine(0, 100, 100, 1000) +   // start: pose at the origin
                             minesLine(1, 2100, 2100, 1000) +  // both wheels one turn: straight ahead
                             minesLine(2, 1100, 3100, 1000));  // left back, right forward: turn in place
  MinesLogReader reader(file.path());
  ScanRecord r;
  ASSERT_TRUE(reader.next(r));
  EXPECT_DOUBLE_EQ(r.scan.pose.x, 0.0);
  ASSERT_TRUE(reader.next(r));
  EXPECT_NEAR(r.scan.pose.x, wheel_turn, 1e-12);
  EXPECT_NEAR(r.scan.pose.y, 0.0, 1e-12);
  EXPECT_NEAR(r.scan.pose.theta, 0.0, 1e-12);
  ASSERT_TRUE(reader.next(r));
  EXPECT_NEAR(r.scan.pose.x, wheel_turn, 1e-12) << "turning in place does not move the centre";
  EXPECT_NEAR(r.scan.pose.theta, wheel_turn / (2 * 0.165), 1e-12) << "right wheel forward turns counter-clockwise";
}

TEST(MinesLog, BadLinesNameFileLineAndField) {
  TempFile short_line("c.dat", minesLine(0, 0, 0, 1000) + "1 2 3\n");
  MinesLogReader reader(short_line.path());
  ScanRecord r;
  ASSERT_TRUE(reader.next(r));
  try {
    reader.next(r);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(short_line.path() + ":2"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("707"), std::string::npos) << e.what();
  }
  std::string bad = minesLine(0, 0, 0, 1000);
  bad.replace(bad.find(" 1000 "), 6, " 1x00 ");
  TempFile bad_range("d.dat", bad);
  MinesLogReader bad_reader(bad_range.path());
  EXPECT_THROW(bad_reader.next(r), InputError);
}

TEST(MinesLog, ReadsTheRealLogs) {
  const std::filesystem::path dir = std::filesystem::path(SCANFILTER_SHARED_DATA) / "real/mines_urg04lx";
  if (!std::filesystem::exists(dir / "exp2.dat")) GTEST_SKIP() << "no " << dir;
  auto source = openScanSource((dir / "exp2.dat").string());
  ScanRecord r;
  std::size_t scans = 0, returns = 0, beams = 0;
  while (source->next(r)) {
    ++scans;
    beams += r.scan.size();
    for (std::size_t i = 0; i < r.scan.size(); ++i) returns += r.scan.hasReturn(i);
  }
  EXPECT_EQ(scans, 641u);  // SOURCES.md
  EXPECT_EQ(beams, 641u * 682u);
  // SOURCES.md: 55.3 % zeros and 2.5 % error codes, so about 42 % returns.
  EXPECT_NEAR(static_cast<double>(returns) / static_cast<double>(beams), 0.422, 0.01);
}

}  // namespace
}  // namespace scanfilter
