// `scanfilter report-real`: what the two-step filter does to real recordings
// (no truth): points removed by reason, occupancy maps from filtered and
// unfiltered scans side by side, how pose error (odometry drift, pose jumps)
// moves the penetration step, and every filter's removals against the
// returns seen again from elsewhere (multi-view consistency).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "commands.hpp"
#include "real_consistency_report.hpp"
#include "table_numbers.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/map_files.hpp"
#include "scanfilter/map_picture.hpp"
#include "scanfilter/mines_log_reader.hpp"
#include "scanfilter/occupancy_grid.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/sim/odometry_drift.hpp"
#include "scanfilter/two_step_filter.hpp"

namespace scanfilter::cli {

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kNoPoseJumpReset = 1e9;  // m: a threshold no log reaches

struct RecordedLog {
  std::string name;
  std::string source;
  SensorInfo sensor;
  std::vector<Scan> scans;
};

RecordedLog readLog(const std::string& path, double carmen_range_max) {
  ScanSourceOptions options;
  options.carmen_range_max = carmen_range_max;
  auto source = openScanSource(path, options);
  RecordedLog log{std::filesystem::path(path).filename().string(), source->header().source, source->header().sensor, {}};
  ScanRecord record;
  while (source->next(record)) log.scans.push_back(std::move(record.scan));
  return log;
}

// One way of replaying a log: the filter config and the poses it sees. The
// log as recorded also gets its maps drawn.
struct Condition {
  std::string name;
  FilterConfig config;
  sim::OdometryDrift drift{};
  bool as_recorded = false;
};

struct ReplayResult {
  std::size_t returns = 0, jump = 0, misdetected = 0, resets = 0;
  double millis_per_scan = 0.0;
  std::vector<std::vector<std::uint8_t>> labels;
};

// keep_labels: also return every scan's labels (for the maps).
ReplayResult replay(const RecordedLog& log, const std::vector<Scan>& scans, const FilterConfig& config,
                    bool keep_labels) {
  TwoStepFilter filter(config.resolve(log.sensor), Implementation::kFast);
  ReplayResult out;
  std::chrono::duration<double> elapsed{0};
  std::vector<std::uint8_t> labels;
  for (const auto& scan : scans) {
    labels.resize(scan.size());
    const auto start = std::chrono::steady_clock::now();
    filter.apply(scan, log.sensor, labels);
    elapsed += std::chrono::steady_clock::now() - start;
    for (auto code : labels) {
      out.returns += code != static_cast<std::uint8_t>(PointCode::kNoReturn);
      out.jump += code == static_cast<std::uint8_t>(PointCode::kJump);
      out.misdetected += code == static_cast<std::uint8_t>(PointCode::kMisdetected);
    }
    if (keep_labels) out.labels.push_back(labels);
  }
  out.resets = filter.penetration().resetCount();
  out.millis_per_scan = scans.empty() ? 0.0 : 1e3 * elapsed.count() / static_cast<double>(scans.size());
  return out;
}

OccupancyGrid buildMap(const RecordedLog& log, const std::vector<std::vector<std::uint8_t>>* labels) {
  OccupancyGrid grid{OccupancyGridParams{}};
  for (std::size_t i = 0; i < log.scans.size(); ++i)
    grid.integrate(log.scans[i], log.sensor, labels ? (*labels)[i] : std::vector<std::uint8_t>{});
  return grid;
}

std::size_t occupiedCells(const OccupancyGrid& grid) {
  std::size_t n = 0;
  const CellBox box = grid.bounds();
  for (auto y = box.lo.y; y <= box.hi.y; ++y)
    for (auto x = box.lo.x; x <= box.hi.x; ++x) n += grid.probability({x, y}) > grid.params().occupied_threshold;
  return n;
}

void saveSideBySide(const OccupancyGrid& unfiltered, const OccupancyGrid& filtered, const std::string& title,
                    const std::string& path) {
  CellBox box = unfiltered.bounds();
  box.include(filtered.bounds().lo);
  box.include(filtered.bounds().hi);
  mapPicture({mapImage(unfiltered, box), mapImage(filtered, box)}, unfiltered.params().resolution,
             title + ": UNFILTERED (LEFT), FILTERED (RIGHT)")
      .save(path);
}


std::vector<Condition> conditions(const FilterConfig& base) {
  std::vector<Condition> out;
  out.push_back({"as recorded", base, {}, true});
  for (double lifetime : {1.0, 0.5}) {
    FilterConfig c = base;
    c.params.penetration.frame_lifetime = lifetime;
    out.push_back({fmt("T_max %.1f s", lifetime), c});
  }
  FilterConfig no_reset = base;
  no_reset.params.penetration.pose_jump_reset = kNoPoseJumpReset;
  out.push_back({"no pose-jump reset", no_reset});
  out.push_back({"+ drift 1 %, 0.5°/m", base, {0.01, 0.5 * kDeg}});
  out.push_back({"+ drift 3 %, 2°/m", base, {0.03, 2.0 * kDeg}});
  return out;
}

}  // namespace

int runReportReal(const ReportRealOptions& options) {
  const FilterConfig base = options.config.empty() ? FilterConfig{} : loadFilterConfig(options.config);
  const std::optional<FilterConfig> literal =
      options.literal_config.empty() ? std::nullopt : std::optional(loadFilterConfig(options.literal_config));
  RealConsistencyReport consistency(consistencyFilters(base, literal));
  if (!options.output_dir.empty()) std::filesystem::create_directories(options.output_dir);
  std::ostringstream report;
  report << "| log | poses | condition | scans | returns | jump removed | misdetected removed | cache resets | ms / scan |\n"
         << "|---|---|---|---|---|---|---|---|---|\n";
  std::ostringstream maps;
  maps << "\n| log | occupied cells unfiltered | filtered | picture |\n|---|---|---|---|\n";
  for (const auto& path : options.logs) {
    // Progress once the log has read: a bad file gets its one error line only.
    const RecordedLog log = readLog(path, options.carmen_range_max);
    std::cerr << "report-real: " << path << " (" << log.scans.size() << " scans)\n";
    const std::string stem = std::filesystem::path(log.name).stem().stem().string();
    const bool odometry_only = log.source.starts_with(MinesLogReader::kSourcePrefix);
    const std::string poses = odometry_only ? "wheel odometry" : "as logged";
    for (const auto& condition : conditions(base)) {
      std::vector<Scan> scans = log.scans;
      sim::applyOdometryDrift(scans, condition.drift);
      const ReplayResult r = replay(log, scans, condition.config, condition.as_recorded);
      report << "| " << log.name << " | " << poses << " | " << condition.name << " | " << scans.size() << " | "
             << r.returns << " | " << r.jump << " (" << pct(r.jump, r.returns) << ") | " << r.misdetected << " ("
             << pct(r.misdetected, r.returns) << ") | " << r.resets << " | " << fmt("%.3f", r.millis_per_scan) << " |\n";
      if (!condition.as_recorded) continue;
      const OccupancyGrid filtered = buildMap(log, &r.labels), unfiltered = buildMap(log, nullptr);
      std::string picture = "-";
      if (!options.output_dir.empty()) {
        picture = "real-map-" + stem + ".png";
        saveSideBySide(unfiltered, filtered, log.name, (std::filesystem::path(options.output_dir) / picture).string());
      }
      const std::string shown = picture == "-" ? picture : "![" + log.name + "](" + options.image_prefix + picture + ")";
      maps << "| " << log.name << " | " << occupiedCells(unfiltered) << " | " << occupiedCells(filtered) << " | "
           << shown << " |\n";
    }
    const std::string picture = "real-consistency-" + stem + ".png";
    consistency.add({log.name, log.sensor, log.scans},
                    options.output_dir.empty() ? "" : (std::filesystem::path(options.output_dir) / picture).string(),
                    options.image_prefix + picture);
  }
  report << maps.str();
  std::ostringstream consistency_tables;
  consistency.write(consistency_tables);
  if (!options.output_dir.empty()) {
    const std::filesystem::path dir(options.output_dir);
    std::ofstream((dir / "real-recordings.md").string()) << report.str();
    std::ofstream((dir / "real-consistency.md").string()) << consistency_tables.str();
  }
  std::cout << report.str() << "\n" << consistency_tables.str();
  return 0;
}

}  // namespace scanfilter::cli
