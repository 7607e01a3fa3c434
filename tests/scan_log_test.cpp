#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "scanfilter/artefact_cause.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/scan_log_reader.hpp"
#include "scanfilter/scan_log_writer.hpp"
#include "scanfilter/scan_source.hpp"
#include "temp_file.hpp"

namespace scanfilter {
namespace {

using test::TempFile;

const std::string kHeader =
    R"({"scanlog": 1, "source": "unit test", "sensor": {"mount": [-0.05, 0.0, 3.141592653589793], "direction": "cw", "range_min": 0.15, "range_max": 6.0, "angular_accuracy_deg": 1.0}})";
const std::string kScan =
    R"({"stamp": 12.3, "pose": [1.2, -0.35, 0.7854], "angle_min": 0.0, "angle_increment": 0.0174532925, "ranges": [2.31, 2.30, 0.0, null, 5.98], "intensities": [812, 790, 0, 0, 120], "truth": [0, 0, 3, 3, 2], "vendor_key": {"kept": true}})";

std::vector<ScanRecord> readAll(const std::string& path) {
  ScanLogReader reader(path);
  std::vector<ScanRecord> out;
  ScanRecord r;
  while (reader.next(r)) out.push_back(r);
  return out;
}

// The error a log with `scan_line` as its only scan gives, as text.
std::string errorOf(const std::string& scan_line, const std::string& header = kHeader) {
  TempFile file("bad.scanlog.jsonl", header + "\n" + scan_line + "\n");
  try {
    readAll(file.path());
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.path());
    return std::string(e.what()).substr(file.path().size());
  }
  return "no error";
}

TEST(ScanLog, ReadsTheFormatExample) {
  TempFile file("example.scanlog.jsonl", kHeader + "\n" + kScan + "\n");
  ScanLogReader reader(file.path());
  EXPECT_EQ(reader.header().source, "unit test");
  EXPECT_EQ(reader.header().sensor.direction, BeamDirection::kCw);
  EXPECT_DOUBLE_EQ(reader.header().sensor.mount.x, -0.05);
  ScanRecord r;
  ASSERT_TRUE(reader.next(r));
  EXPECT_EQ(r.scan.stamp.toDecimal(), "12.3");
  ASSERT_EQ(r.scan.size(), 5u);
  EXPECT_DOUBLE_EQ(r.scan.ranges[0], 2.31);
  EXPECT_TRUE(std::isnan(r.scan.ranges[2])) << "0 is no return";
  EXPECT_TRUE(std::isnan(r.scan.ranges[3])) << "null is no return";
  EXPECT_EQ(r.scan.truth, (std::vector<std::uint8_t>{0, 0, 3, 3, 2}));
  EXPECT_EQ(r.line, 2u);
  EXPECT_FALSE(reader.next(r));
}

TEST(ScanLog, RoundTripKeepsEveryKeyAndAddsLabels) {
  TempFile in("in.scanlog.jsonl", kHeader + "\n" + kScan + "\n");
  TempFile out("out.scanlog.jsonl");
  {
    ScanLogReader reader(in.path());
    ScanLogWriter writer(out.path(), reader.header());
    ScanRecord r;
    while (reader.next(r)) {
      r.scan.labels = {0, 1, 3, 3, 2};
      writer.write(r);
    }
    writer.close();
  }
  const auto records = readAll(out.path());
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].scan.labels, (std::vector<std::uint8_t>{0, 1, 3, 3, 2}));
  EXPECT_EQ(records[0].original["vendor_key"]["kept"], true) << "unknown keys are kept";
  EXPECT_EQ(records[0].original["ranges"][2], 0.0) << "the input's own values are kept";
  EXPECT_DOUBLE_EQ(records[0].scan.ranges[4], 5.98);
}

// A scan serialised from memory (no original line) into a log with a
// 0.1-10 m sensor, and the records read back.
std::vector<ScanRecord> writtenAndReadBack(const Scan& scan) {
  ScanLogHeader header;
  header.sensor.range_min = 0.1;
  header.sensor.range_max = 10;
  TempFile out("serialised.scanlog.jsonl");
  {
    ScanLogWriter writer(out.path(), header);
    writer.write(ScanRecord{scan, {}, 0});
    writer.close();
  }
  return readAll(out.path());
}

TEST(ScanLog, SerialisedScanRoundTrips) {
  Scan s;
  s.stamp = Stamp::fromSeconds(1.5);
  s.pose = {1, 2, 3};
  s.angle_increment = 0.1;
  s.ranges = {1.0, std::nan(""), 2.5};
  s.truth = {0, 3, 1};
  s.thin_leg_beams = {0};
  s.truth_cause = {0, 0, static_cast<std::uint8_t>(ArtefactCause::kEdgeMix)};
  const auto records = writtenAndReadBack(s);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].scan.truth, s.truth);
  EXPECT_EQ(records[0].scan.thin_leg_beams, s.thin_leg_beams);
  EXPECT_EQ(records[0].scan.truth_cause, s.truth_cause);
  EXPECT_TRUE(std::isnan(records[0].scan.ranges[1]));
}

TEST(ScanLog, OutOfRangeValuesAreNoReturn) {
  TempFile file("range.scanlog.jsonl", kHeader + "\n" +
      R"({"stamp": 0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [0.1, 6.5, "NaN", 3.0]})" + "\n");
  const auto records = readAll(file.path());
  const auto& r = records[0].scan.ranges;
  EXPECT_TRUE(std::isnan(r[0]));
  EXPECT_TRUE(std::isnan(r[1]));
  EXPECT_TRUE(std::isnan(r[2]));
  EXPECT_DOUBLE_EQ(r[3], 3.0);
}

TEST(ScanLogErrors, MalformedJsonNamesTheColumnAndALineCutShort) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,)"),
            ":2: malformed JSON at column 29: syntax error while parsing value - unexpected end of input; expected "
            "'[', '{', or a literal (the line ends inside its object: a file cut short?)");
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0] x})"),
            ":2: malformed JSON at column 32: syntax error while parsing object - invalid literal; last read: "
            "'0] x'; expected '}'");
}

TEST(ScanLogErrors, BareNaNIsNotJson) {
  EXPECT_NE(errorOf(R"({"stamp": NaN, "pose": [0,0,0]})").find(":2: malformed JSON"), std::string::npos);
}

TEST(ScanLogErrors, MissingField) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})"), ":2: pose: missing");
}

TEST(ScanLogErrors, NaNPose) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0, "NaN", 0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})"),
            ":2: pose[1]: expected a number, got \"NaN\"");
}

TEST(ScanLogErrors, WrongPoseLength) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0, 0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})"),
            ":2: pose: expected an array of 3 numbers [x, y, theta], got [0,0]");
}

TEST(ScanLogErrors, WrongIntensitiesLength) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1, 2], "intensities": [5]})"),
            ":2: intensities: has 1 entries, ranges has 2; expected equal lengths");
}

TEST(ScanLogErrors, WrongTruthLength) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1, 2], "truth": [0, 0, 0]})"),
            ":2: truth: has 3 entries, ranges has 2; expected equal lengths");
}

TEST(ScanLogErrors, BadPointCode) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1, 2], "labels": [0, 7]})"),
            ":2: labels[1]: expected a point code 0-3, got 7");
}

TEST(ScanLogErrors, BadArtefactCause) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1, 2], "truth_cause": [1, 7]})"),
            ":2: truth_cause[1]: expected an artefact cause 0-6, got 7");
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1, 2], "truth_cause": [1]})"),
            ":2: truth_cause: has 1 entries, ranges has 2; expected equal lengths");
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1, 2], "truth_cause": 1})"),
            ":2: truth_cause: expected an array of artefact causes");
}

TEST(ScanLogErrors, NegativeRange) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1, -2.5]})"),
            ":2: ranges[1]: is negative (-2.5); expected >= 0 or null");
}

TEST(ScanLogErrors, HugeRange) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1e30]})"),
            ":2: ranges[0]: 1e+30 m is beyond any indoor sensor; expected <= 10000 m or null");
}

TEST(ScanLogErrors, EmptyScan) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": []})"),
            ":2: ranges: is empty; a scan needs at least one beam");
}

TEST(ScanLogErrors, ZeroAngleIncrement) {
  EXPECT_EQ(errorOf(R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0, "ranges": [1]})"),
            ":2: angle_increment: is 0; expected a non-zero step");
}

// What one command writes every other reads: a stamp going backwards (real
// logs have them) is counted and the scan kept in file order.
TEST(ScanLog, StampsGoingBackwardsAreCountedAndKept) {
  const std::string a = R"({"stamp": 2.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})";
  const std::string b = R"({"stamp": 1.5, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})";
  TempFile file("back.scanlog.jsonl", kHeader + "\n" + a + "\n" + b + "\n" + a + "\n");
  ScanLogReader reader(file.path());
  ScanRecord r;
  std::vector<std::string> stamps;
  while (reader.next(r)) stamps.push_back(r.scan.stamp.toDecimal());
  EXPECT_EQ(stamps, (std::vector<std::string>{"2", "1.5", "2"}));
  EXPECT_EQ(reader.stampRegressions(), 1u);
  EXPECT_EQ(reader.stampRepeats(), 0u);
}

// A stamp equal to the one before is counted as a repeat, not a regression.
TEST(ScanLog, StampsEqualToTheScanBeforeAreCountedAndKept) {
  const std::string a = R"({"stamp": 2.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})";
  const std::string b = R"({"stamp": 3.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})";
  TempFile file("same.scanlog.jsonl", kHeader + "\n" + a + "\n" + a + "\n" + b + "\n" + b + "\n" + b + "\n");
  ScanLogReader reader(file.path());
  ScanRecord r;
  std::size_t scans = 0;
  while (reader.next(r)) ++scans;
  EXPECT_EQ(scans, 5u);
  EXPECT_EQ(reader.stampRepeats(), 3u);
  EXPECT_EQ(reader.stampRegressions(), 0u);
}

// A player reads a log through once before publishing any of it.
TEST(ScanLog, CheckedToItsEndBeforeItIsPlayed) {
  const std::string a = R"({"stamp": 2.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})";
  const std::string b = R"({"stamp": 1.0, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})";
  TempFile good("good.scanlog.jsonl", kHeader + "\n" + a + "\n" + a + "\n" + b + "\n");
  const LogCheck check = checkLogToEnd(good.path());
  EXPECT_EQ(check.scans, 3u);
  EXPECT_EQ(check.stamp_repeats, 1u);
  EXPECT_EQ(check.stamp_regressions, 1u);

  TempFile cut("cut.scanlog.jsonl", kHeader + "\n" + a + "\n" + a + "\n" + a.substr(0, 30));
  try {
    checkLogToEnd(cut.path());
    FAIL() << "a log cut short passed its check";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 4u);
  }
}

// Stamps a double cannot hold (about 240 ns apart at 1.7e9 s) are read as
// integer nanoseconds and written back the same.
TEST(ScanLog, StampsSurviveToTheNanosecond) {
  const std::vector<std::string> stamps = {"1732000000.200700001", "1732000000.200700002", "1732000000.9999999",
                                           "1732000001"};
  std::string text = kHeader + "\n";
  for (const auto& s : stamps)
    text += R"({"stamp": )" + s + R"(, "pose": [0,0,0], "angle_min": 0, "angle_increment": 0.1, "ranges": [1]})" + "\n";
  TempFile in("ns.scanlog.jsonl", text);
  TempFile out("ns-out.scanlog.jsonl");
  {
    ScanLogReader reader(in.path());
    ScanLogWriter writer(out.path(), reader.header());
    ScanRecord r;
    while (reader.next(r)) writer.write(r);
    writer.close();
  }
  const auto records = readAll(out.path());
  ASSERT_EQ(records.size(), stamps.size());
  for (std::size_t k = 0; k < stamps.size(); ++k) EXPECT_EQ(records[k].scan.stamp.toDecimal(), stamps[k]);
  EXPECT_EQ(records[0].scan.stamp.nanoseconds(), 1732000000200700001);
  EXPECT_EQ(records[1].scan.stamp.nanoseconds() - records[0].scan.stamp.nanoseconds(), 1);
  // The stamp's text in the file is exactly what was read.
  std::ifstream file(out.path());
  std::string header, first;
  std::getline(file, header);
  std::getline(file, first);
  EXPECT_EQ(first.rfind(R"({"stamp":1732000000.200700001,)", 0), 0u) << first;
}

// A scan serialised from memory writes its ranges as the source gave them:
// +inf and out-of-limit readings survive a write and a read.
TEST(ScanLog, RecordedRangesAreWrittenAsGiven) {
  Scan s;
  s.stamp = Stamp::fromNanoseconds(7);
  s.angle_increment = 0.1;
  const double inf = std::numeric_limits<double>::infinity();
  s.ranges = {1.0, std::nan(""), std::nan(""), std::nan("")};
  s.recorded_ranges = {1.0, inf, 12.5, std::nan("")};
  const auto records = writtenAndReadBack(s);
  ASSERT_EQ(records.size(), 1u);
  const Scan& back = records[0].scan;
  EXPECT_EQ(back.stamp.nanoseconds(), 7);
  EXPECT_EQ(back.recorded_ranges[1], inf);
  EXPECT_EQ(back.recorded_ranges[2], 12.5);
  EXPECT_TRUE(std::isnan(back.recorded_ranges[3]));
  for (std::size_t i = 1; i < 4; ++i) EXPECT_FALSE(back.hasReturn(i)) << "beam " << i << " is no return";
}

TEST(ScanLogErrors, BadHeader) {
  EXPECT_EQ(errorOf("", R"({"scanlog": 2})"), ":1: scanlog: unsupported version 2; expected 1");
  EXPECT_EQ(errorOf("", R"({"scanlog": 1, "sensor": {"mount": [0,0,0], "direction": "up"}})"),
            ":1: sensor.direction: expected \"ccw\" or \"cw\", got \"up\"");
  EXPECT_EQ(errorOf("", R"({"scanlog": 1, "sensor": {"mount": [0,0,0], "direction": "cw", "range_min": 2, "range_max": 1, "angular_accuracy_deg": 1}})"),
            ":1: sensor.range_max: must exceed range_min (2.000000)");
}

TEST(ScanLogErrors, EmptyAndMissingFiles) {
  TempFile empty("empty.scanlog.jsonl", " ");
  std::ofstream(empty.path(), std::ios::trunc).close();
  EXPECT_THROW(ScanLogReader{empty.path()}, InputError);
  EXPECT_THROW(ScanLogReader{"/nonexistent/x.scanlog.jsonl"}, InputError);
}

}  // namespace
}  // namespace scanfilter
