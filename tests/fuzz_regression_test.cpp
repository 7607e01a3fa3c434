// Regression tests for the inputs the fuzz targets (fuzz/) and the bad-input
// review found: each once crashed, hit undefined behaviour, escaped as an
// exception other than InputError, or took unbounded memory. Each input is
// also in the target's seed corpus (fuzz/corpus/<target>/), so every fuzz
// run replays it too.
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "scanfilter/carmen_log_reader.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/line_reader.hpp"
#include "scanfilter/mines_log_reader.hpp"
#include "scanfilter/scan_log_reader.hpp"
#include "scanfilter/scan_log_writer.hpp"
#include "scanfilter/sim/scene.hpp"
#include "scanfilter/sim/sensor_preset.hpp"
#include "temp_file.hpp"

namespace scanfilter {
namespace {

using test::TempFile;

// The InputError message reading `path` with `read` gives; "" if none.
template <typename Read>
std::string errorOf(Read&& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void readAll(ScanSource& source) {
  ScanRecord record;
  while (source.next(record)) {
  }
}

std::string corpusFile(const std::string& target, const std::string& name) {
  std::ifstream in(std::string(SCANFILTER_SOURCE_DIR) + "/fuzz/corpus/" + target + "/" + name, std::ios::binary);
  EXPECT_TRUE(in.good()) << "missing corpus file " << target << "/" << name;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// num_readings 1e300 was cast to size_t: undefined behaviour (UBSan
// float-cast-overflow) before the field count was checked.
TEST(FuzzRegression, CarmenHugeReadingCount) {
  TempFile log("huge-count.log", corpusFile("carmen_reader_fuzz", "regression-huge-num-readings.log"));
  const std::string error = errorOf([&] {
    CarmenLogReader reader(log.path(), {});
    readAll(reader);
  });
  EXPECT_NE(error.find(":1: num_readings: expected a positive integer up to the line's field count"), std::string::npos)
      << error;
}

// A negative num_remissions was cast to size_t (undefined behaviour).
TEST(FuzzRegression, CarmenNegativeRemissionCount) {
  TempFile log("negative-remissions.log", corpusFile("carmen_reader_fuzz", "regression-negative-remissions.log"));
  const std::string error = errorOf([&] {
    CarmenLogReader reader(log.path(), {});
    readAll(reader);
  });
  EXPECT_NE(error.find(":1: num_remissions: expected an integer >= 0"), std::string::npos) << error;
}

// A time in µs beyond ±9.2e15 overflowed int64 when turned into nanoseconds.
TEST(FuzzRegression, MinesStampOutOfRange) {
  std::string line = "9223372036854776 0 0 0";
  for (int i = 4; i < 707; ++i) line += " 1000";
  TempFile log("big-stamp.dat", line + "\n");
  const std::string error = errorOf([&] {
    MinesLogReader reader(log.path());
    readAll(reader);
  });
  EXPECT_NE(error.find(":1: timestamp_us: '9223372036854776' is out of range"), std::string::npos) << error;
}

// Tick counters from one extreme to the other: their int64 difference
// overflowed (undefined behaviour); in double it is a huge distance, and the
// pose it gives is rejected as corrupt.
TEST(FuzzRegression, MinesTickCountersFarApart) {
  auto line = [](const std::string& stamp, const std::string& ticks) {
    std::string l = stamp + " 0 " + ticks + " " + ticks;
    for (int i = 4; i < 707; ++i) l += " 1000";
    return l + "\n";
  };
  TempFile log("ticks.dat", line("1", "-9223372036854775807") + line("2", "9223372036854775807"));
  MinesLogReader reader(log.path());
  ScanRecord record;
  EXPECT_TRUE(reader.next(record));
  const std::string error = errorOf([&] { reader.next(record); });
  EXPECT_NE(error.find(":2: left_ticks/right_ticks: dead-reckoned pose more than 1000000 m"), std::string::npos) << error;
}

// A label of 2^32 was read as an int, wrapped to 0 and accepted as "valid".
TEST(FuzzRegression, ScanLogLabelBeyondInt) {
  TempFile log("big-label.scanlog.jsonl",
               R"({"scanlog":1,"sensor":{"mount":[0,0,0],"direction":"ccw","range_min":0.1,"range_max":10,"angular_accuracy_deg":1}})"
               "\n"
               R"({"stamp":1,"pose":[0,0,0],"angle_min":0,"angle_increment":0.1,"ranges":[1,2],"labels":[4294967296,0]})"
               "\n");
  const std::string error = errorOf([&] {
    ScanLogReader reader(log.path());
    readAll(reader);
  });
  EXPECT_NE(error.find(":2: labels[0]: expected a point code 0-3, got 4294967296"), std::string::npos) << error;
}

// A number beyond a double (1e400) made nlohmann throw out_of_range, which
// escaped the reader instead of an InputError naming the line.
TEST(FuzzRegression, ScanLogNumberBeyondDouble) {
  TempFile log("overflow.scanlog.jsonl",
               R"({"scanlog":1,"sensor":{"mount":[0,0,0],"direction":"ccw","range_min":0.1,"range_max":10,"angular_accuracy_deg":1}})"
               "\n"
               R"({"stamp":1,"pose":[1e400,0,0],"angle_min":0,"angle_increment":0.1,"ranges":[1,2]})"
               "\n");
  const std::string error = errorOf([&] {
    ScanLogReader reader(log.path());
    readAll(reader);
  });
  EXPECT_NE(error.find(":2: unreadable JSON: [json.exception.out_of_range.406] number overflow"), std::string::npos) << error;
  TempFile corpus("overflow-corpus.scanlog.jsonl", corpusFile("scan_log_reader_fuzz", "regression-number-overflow.jsonl"));
  EXPECT_NO_THROW(errorOf([&] {
    ScanLogReader reader(corpus.path());
    readAll(reader);
  }));
}

// A mapping where a word belongs (material, name) and a list used as a key
// escaped as yaml-cpp's TypedBadConversion instead of a located InputError.
TEST(FuzzRegression, SceneNonScalarWhereAWordBelongs) {
  const std::string walls = "walls:\n  - points: [[0, 0], [1, 0]]\n    material: {a: 1}\n"
                            "trajectory:\n  waypoints: [[0, 0], [1, 1]]\n";
  EXPECT_NE(errorOf([&] { sim::parseScene(walls, "s.yaml"); }).find("s.yaml:3: walls[0].material: expected a string"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { sim::parseScene("name: [a]\n", "s.yaml"); }).find("s.yaml:1: name: expected a string"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { sim::parseScene("[a]: 1\n", "s.yaml"); }).find("s.yaml:1: scene: expected plain keys"),
            std::string::npos);
}

// sensor_preset_fuzz (campaign 4): `beams: 1.4e76` was converted to int
// (undefined behaviour); counts are now bounded, with a located error.
TEST(FuzzRegression, SensorPresetBeamsBeyondAnInt) {
  sim::Scene scene = sim::findScene("hall");
  for (const std::string beams : {"14555555555555555555555555555555555555555555555555555555555555555555555555540",
                                  "100001", "2147483648"}) {
    const TempFile preset("huge-beams.yaml", "name: huge\nsensor:\n  range_max: 8\n  beams: " + beams + "\n");
    const std::string error = errorOf([&] { sim::applySensor(scene, preset.path()); });
    EXPECT_NE(error.find(":4: sensor.beams: expected a whole number from 1 to 100000"), std::string::npos) << error;
  }
  const TempFile fine("fine-beams.yaml", "name: fine\nsensor:\n  range_max: 8\n  beams: 100000\n");
  sim::applySensor(scene, fine.path());
  EXPECT_EQ(scene.lidar.beams, 100000);
}

TEST(FuzzRegression, FilterConfigListAsKey) {
  const std::string error = errorOf([&] { parseFilterConfig("jump_filter:\n  [alpha]: 1\n", "f.yaml"); });
  EXPECT_NE(error.find("f.yaml:2: "), std::string::npos) << error;
  EXPECT_NE(errorOf([&] { parseFilterConfig("? [a]\n: 1\n", "f.yaml"); }).find("expected a plain key"),
            std::string::npos);
}

// A line with no end (a 2 GB line) was read into memory whole; now the
// reader stops at LineReader::kMaxLineBytes. The 70 MiB line is written
// gzip-compressed: ~70 kB on disk.
TEST(FuzzRegression, LineLongerThanTheLimit) {
  TempFile log("long-line.log.gz");
  gzFile out = gzopen(log.path().c_str(), "wb9");
  ASSERT_NE(out, nullptr);
  const std::string block(1 << 20, 'x');
  for (int i = 0; i < 70; ++i) ASSERT_EQ(gzwrite(out, block.data(), static_cast<unsigned>(block.size())), static_cast<int>(block.size()));
  gzclose(out);
  const std::string error = errorOf([&] { openScanSource(log.path()); });
  EXPECT_NE(error.find(":1: line longer than 64 MiB"), std::string::npos) << error;
}

TEST(FuzzRegression, DirectoryEmptyAndTruncatedGzip) {
  const std::string dir = ::testing::TempDir();
  EXPECT_NE(errorOf([&] { openScanSource(dir); }).find("is a directory"), std::string::npos);
  TempFile empty("empty.log");
  std::ofstream(empty.path()).close();
  EXPECT_NE(errorOf([&] { openScanSource(empty.path()); }).find("empty file"), std::string::npos);

  // A scan log, gzip-compressed and cut in half.
  std::string text = R"({"scanlog":1,"sensor":{"mount":[0,0,0],"direction":"ccw","range_min":0.1,"range_max":10,"angular_accuracy_deg":1}})"
                     "\n";
  for (int i = 1; i <= 2000; ++i)
    text += R"({"stamp":)" + std::to_string(i) + R"(,"pose":[0,0,0],"angle_min":0,"angle_increment":0.1,"ranges":[1,2,3]})" "\n";
  TempFile gz("truncated.scanlog.jsonl.gz");
  gzFile out = gzopen(gz.path().c_str(), "wb9");
  gzwrite(out, text.data(), static_cast<unsigned>(text.size()));
  gzclose(out);
  std::filesystem::resize_file(gz.path(), std::filesystem::file_size(gz.path()) / 2);
  const std::string error = errorOf([&] { readAll(*openScanSource(gz.path())); });
  EXPECT_NE(error.find("truncated.scanlog.jsonl.gz:"), std::string::npos) << error;
}

// A writer that never got to close() (an error on the way) leaves nothing
// under the real name, nor its temporary file.
TEST(FuzzRegression, ScanLogWriterLeavesNoPartialFile) {
  TempFile out("partial.scanlog.jsonl");
  {
    ScanLogWriter writer(out.path(), ScanLogHeader{});
    EXPECT_TRUE(std::filesystem::exists(out.path() + ".partial"));
  }
  EXPECT_FALSE(std::filesystem::exists(out.path()));
  EXPECT_FALSE(std::filesystem::exists(out.path() + ".partial"));
  {
    ScanLogWriter writer(out.path(), ScanLogHeader{});
    writer.close();
  }
  EXPECT_TRUE(std::filesystem::exists(out.path()));
  EXPECT_FALSE(std::filesystem::exists(out.path() + ".partial"));
}

}  // namespace
}  // namespace scanfilter
