// What the two-step filter removes on real recordings, split by the step that
// removed it, against the multi-view consistency of the log
// (docs/accuracy.md, "Real recordings"): for each filter config, per log and
// per step, the share of re-observed returns removed (the false-deletion
// proxy) and of never re-observed ones, and the selectivity of both steps
// together. Several configs side by side, the consistency built once per log:
// the tool for tuning against real data.
//   build/bench/real_removal_breakdown --config config/filter.yaml [--config B.yaml ...] LOG...
// --dump FILE writes every removed return (log, scan, beam, range, step,
// incidence, re-observed or not) of the first config as CSV, to look at what is deleted.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "scanfilter/consistency_score.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/incidence_angle.hpp"
#include "scanfilter/multiview_consistency.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/two_step_filter.hpp"

using namespace scanfilter;

namespace {

struct RecordedLog {
  std::string name;
  SensorInfo sensor;
  std::vector<Scan> scans;
};

RecordedLog readLog(const std::string& path) {
  auto source = openScanSource(path);
  RecordedLog log{std::filesystem::path(path).filename().string(), source->header().sensor, {}};
  ScanRecord record;
  while (source->next(record)) log.scans.push_back(std::move(record.scan));
  return log;
}

constexpr int kDumpNeighbours = 3;  // beams either side whose ranges the dump lists

using Labels = std::vector<std::vector<std::uint8_t>>;

Labels runFilter(const RecordedLog& log, const FilterConfig& config) {
  TwoStepFilter filter(config.resolve(log.sensor), Implementation::kFast);
  Labels labels(log.scans.size());
  for (std::size_t s = 0; s < log.scans.size(); ++s) {
    labels[s].resize(log.scans[s].size());
    filter.apply(log.scans[s], log.sensor, labels[s]);
  }
  return labels;
}

// Removed re-observed / never re-observed returns of one step.
struct StepCounts {
  std::size_t reobserved = 0, not_reobserved = 0;
};

double percent(std::size_t part, std::size_t whole) { return whole ? 100.0 * part / whole : NAN; }

// The range of the beam `step` away (NaN without a return there or past the end).
double neighbourRange(const Scan& scan, std::size_t i, int step) {
  const auto j = static_cast<std::int64_t>(i) + step;
  if (j < 0 || j >= static_cast<std::int64_t>(scan.size()) || !scan.hasReturn(static_cast<std::size_t>(j))) return NAN;
  return scan.ranges[static_cast<std::size_t>(j)];
}

void dumpRemovedReobserved(std::ofstream& out, const RecordedLog& log, const ReobservationMap& seen,
                           const Labels& labels) {
  const MultiviewParams params;
  for (std::size_t s = 0; s < log.scans.size(); ++s) {
    const std::vector<double> incidence = incidenceAnglesDeg(log.scans[s], log.sensor, params.surface_tolerance);
    for (std::size_t i = 0; i < labels[s].size(); ++i) {
      if (!isRemovedCode(labels[s][i]) || seen[s][i] == Reobservation::kNoReturn) continue;
      out << log.name << "," << s << "," << i << "," << log.scans[s].ranges[i] << ","
          << static_cast<int>(labels[s][i]) << "," << incidence[i] << ","
          << (seen[s][i] == Reobservation::kReobserved) << "," << static_cast<int>(seen[s][i]);
      for (int step = -kDumpNeighbours; step <= kDumpNeighbours; ++step) out << "," << neighbourRange(log.scans[s], i, step);
      out << "\n";
    }
  }
}

// One line per log and config: removals by step against re-observation.
void report(const std::vector<std::string>& configs, const std::vector<std::string>& logs, const std::string& dump) {
  std::vector<FilterConfig> filters;
  for (const auto& path : configs) filters.push_back(loadFilterConfig(path));
  std::ofstream dump_out;
  if (!dump.empty()) dump_out.open(dump), dump_out << "log,scan,beam,range,code,incidence_deg,reobserved,seen,r-3,r-2,r-1,r0,r1,r2,r3\n";

  std::printf("%-32s %-40s %8s %8s %8s %8s %8s %6s\n", "log", "config", "jump:re", "jump:not", "mis:re", "mis:not",
              "all:re", "sel");
  for (const auto& path : logs) {
    const RecordedLog log = readLog(path);
    const MultiviewConsistency measure(log.scans, log.sensor);
    const ReobservationMap& seen = measure.reobservation();
    for (std::size_t c = 0; c < filters.size(); ++c) {
      const Labels labels = runFilter(log, filters[c]);
      const ConsistencyCounts all = measure.score(labels).all;
      StepCounts jump, misdetected;
      for (std::size_t s = 0; s < labels.size(); ++s)
        for (std::size_t i = 0; i < labels[s].size(); ++i) {
          StepCounts* step = labels[s][i] == static_cast<std::uint8_t>(PointCode::kJump)          ? &jump
                             : labels[s][i] == static_cast<std::uint8_t>(PointCode::kMisdetected) ? &misdetected
                                                                                                   : nullptr;
          if (!step || seen[s][i] == Reobservation::kNoReturn) continue;
          (seen[s][i] == Reobservation::kReobserved ? step->reobserved : step->not_reobserved)++;
        }
      std::printf("%-32s %-40s %7.2f%% %7.2f%% %7.2f%% %7.2f%% %7.2f%% %6.2f\n", log.name.c_str(),
                  std::filesystem::path(configs[c]).filename().string().c_str(),
                  percent(jump.reobserved, all.reobserved), percent(jump.not_reobserved, all.notReobserved()),
                  percent(misdetected.reobserved, all.reobserved),
                  percent(misdetected.not_reobserved, all.notReobserved()), 100.0 * all.removedOfReobserved(),
                  all.selectivity());
      if (c == 0 && dump_out.is_open()) dumpRemovedReobserved(dump_out, log, seen, labels);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> configs, logs;
  std::string dump;
  CLI::App app{"Removals of real recordings by step, against multi-view consistency, for several filter configs"};
  app.add_option("--config", configs, "filter config YAML (repeat for several)")
      ->required()
      ->allow_extra_args(false)->check(CLI::ExistingFile);
  app.add_option("--dump", dump, "CSV of the first config's removed returns");
  app.add_option("logs", logs, "CARMEN, Mines or scan logs")->required()->check(CLI::ExistingFile);
  CLI11_PARSE(app, argc, argv);
  spdlog::set_level(spdlog::level::warn);  // the penetration step logs each cache reset
  try {
    report(configs, logs, dump);
  } catch (const std::exception& e) {  // a malformed config or log: say which, not a crash
    std::fprintf(stderr, "real_removal_breakdown: %s\n", e.what());
    return 1;
  }
  return 0;
}
