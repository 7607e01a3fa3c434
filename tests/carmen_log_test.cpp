#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "scanfilter/carmen_log_reader.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/scan_source.hpp"
#include "temp_file.hpp"

namespace scanfilter {
namespace {

using test::TempFile;
constexpr double kPi = std::numbers::pi;

std::string flaser(int n, double first_range, double stamp) {
  std::string line = "FLASER " + std::to_string(n);
  for (int i = 0; i < n; ++i) line += " " + std::to_string(i == 0 ? first_range : 1.0 + 0.01 * i);
  line += " 0.6 -0.03 -0.35 0.6 -0.03 -0.35 " + std::to_string(stamp) + " pippo " + std::to_string(stamp);
  return line;
}

TEST(CarmenLog, ReadsFlaserWithParams) {
  TempFile file("a.log",
                "# message formats defined: PARAM SYNC ODOM FLASER\n"
                "PARAM robot_frontlaser_offset -0.04 1071078718.46 merci 1071078718.46\n"
                "ODOM 0.69 -0.01 -0.23 0 0 0 32.6 pippo 32.6\n" +
                    flaser(180, 81.9, 32.9) + "\nNEFF 27.6 0 pippo 0\n" + flaser(180, 2.5, 33.1) + "\n");
  auto source = openScanSource(file.path());
  EXPECT_DOUBLE_EQ(source->header().sensor.mount.x, -0.04);
  EXPECT_EQ(source->header().sensor.direction, BeamDirection::kCcw);
  EXPECT_NEAR(source->header().sensor.angular_accuracy_deg, 1.0, 1e-12);
  ScanRecord r;
  ASSERT_TRUE(source->next(r));
  EXPECT_EQ(r.line, 4u);
  ASSERT_EQ(r.scan.size(), 180u);
  EXPECT_TRUE(std::isnan(r.scan.ranges[0])) << ">= 80 m is no return";
  EXPECT_NEAR(r.scan.ranges[5], 1.05, 1e-9);
  EXPECT_NEAR(r.scan.angle_min, -kPi / 2, 1e-12);
  EXPECT_NEAR(r.scan.angle_increment, kPi / 180, 1e-12);
  EXPECT_NEAR(r.scan.pose.theta, -0.35, 1e-12);
  EXPECT_EQ(r.scan.stamp.toDecimal(), "32.9");
  ASSERT_TRUE(source->next(r));
  EXPECT_NEAR(r.scan.ranges[0], 2.5, 1e-9);
  EXPECT_FALSE(source->next(r));
}

TEST(CarmenLog, OddBeamCountEndsAtPlusNinety) {
  TempFile file("b.log", flaser(361, 1.0, 1.0) + "\n");
  auto source = openScanSource(file.path());
  ScanRecord r;
  ASSERT_TRUE(source->next(r));
  EXPECT_NEAR(r.scan.angle_min + 360 * r.scan.angle_increment, kPi / 2, 1e-12);
}

TEST(CarmenLog, ReadsRobotLaser1WithAndWithoutRemissions) {
  const std::string ranges = " 1.0 1.1 1.2 1.3";
  const std::string tail = " 0.5 0.6 0.1 0.4 0.6 0.1 0 0 0.5 0.2 10.25 host 10.25";
  TempFile file("c.log", "ROBOTLASER1 0 -1.5708 3.1416 0.01745 80 0.01 0 4" + ranges + tail + "\n" +
                             "ROBOTLASER1 0 -1.5708 3.1416 0.01745 80 0.01 0 4" + ranges + " 4 10 20 30 40" + tail + "\n");
  auto source = openScanSource(file.path());
  ScanRecord r;
  for (int k = 0; k < 2; ++k) {
    ASSERT_TRUE(source->next(r)) << k;
    ASSERT_EQ(r.scan.size(), 4u);
    EXPECT_NEAR(r.scan.pose.x, 0.5, 1e-12);  // the laser pose
    EXPECT_NEAR(r.scan.angle_increment, 0.01745, 1e-12);
    EXPECT_EQ(r.scan.stamp.toDecimal(), "10.25");
  }
}

TEST(CarmenLogErrors, WrongFieldCount) {
  std::string line = flaser(180, 1.0, 1.0);
  line = line.substr(0, line.rfind(' '));  // drop logger_timestamp
  TempFile file("d.log", line + "\n");
  try {
    openScanSource(file.path());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1u);
    EXPECT_EQ(e.field(), "FLASER");
    EXPECT_EQ(e.problem(), "has 190 fields; 180 readings need 191");
  }
}

TEST(CarmenLogErrors, NonNumericRange) {
  std::string line = flaser(4, 1.0, 1.0);
  line.replace(line.find(" 1.010000"), 9, " abc");
  TempFile file("e.log", line + "\n");
  try {
    openScanSource(file.path());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "range (field 4)");
    EXPECT_EQ(e.problem(), "expected a finite number, got \"abc\"");
  }
}

// Real CARMEN logs have stamps that step back (intel: line 5647); the file
// order is the sequence, so such scans are kept and counted, not rejected.
TEST(CarmenLog, StampsGoingBackwardsAreCountedNotFatal) {
  TempFile file("f.log", flaser(4, 1.0, 5.0) + "\n" + flaser(4, 1.0, 4.0) + "\n");
  CarmenLogReader reader(file.path(), {});
  ScanRecord r;
  ASSERT_TRUE(reader.next(r));
  ASSERT_TRUE(reader.next(r));
  EXPECT_EQ(r.scan.stamp.toDecimal(), "4");
  EXPECT_EQ(reader.stampRegressions(), 1u);
}

// The csail log's stamps were written with six significant digits
// ("1.13486e+09"), so most of its scans carry the stamp of the scan before:
// read as written, kept, and counted apart from the regressions.
TEST(CarmenLog, StampsEqualToTheScanBeforeAreCounted) {
  const auto line = [](const std::string& stamp) {
    return "FLASER 2 1.0 1.1 0 0 0 0 0 0 " + stamp + " pippo " + stamp + "\n";
  };
  TempFile file("csail.log", line("1.13486e+09") + line("1.13486e+09") + line("1.13486e+09") + line("1.13487e+09"));
  CarmenLogReader reader(file.path(), {});
  ScanRecord r;
  std::vector<std::string> stamps;
  while (reader.next(r)) stamps.push_back(r.scan.stamp.toDecimal());
  EXPECT_EQ(stamps, (std::vector<std::string>{"1134860000", "1134860000", "1134860000", "1134870000"}));
  EXPECT_EQ(reader.stampRepeats(), 2u);
  EXPECT_EQ(reader.stampRegressions(), 0u);
}

TEST(CarmenLogErrors, NoLaserLines) {
  TempFile file("g.log", "ODOM 0 0 0 0 0 0 1 h 1\n");
  EXPECT_THROW(openScanSource(file.path()), InputError);
}

// The real recordings in shared/ (CI has them beside the checkout).
TEST(CarmenLog, ReadsTheRealIntelLog) {
  const std::string path = std::string(SCANFILTER_SHARED_DATA) + "/real/carmen/intel-corrected.log.gz";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not present";
  auto source = openScanSource(path);
  ScanRecord r;
  std::size_t scans = 0;
  while (source->next(r)) {
    EXPECT_EQ(r.scan.size(), 180u);
    ++scans;
  }
  EXPECT_EQ(scans, 910u);  // SOURCES.md: 910 FLASER scans
}

}  // namespace
}  // namespace scanfilter
