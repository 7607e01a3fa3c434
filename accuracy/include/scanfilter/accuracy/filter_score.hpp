#pragma once
// Scoring a filter over labelled logs: its labels against the truth, and the
// time apply() took.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "scanfilter/filter_config.hpp"
#include "scanfilter/removal_score.hpp"
#include "scanfilter/scan_filter.hpp"
#include "scanfilter/sim/labelled_log.hpp"

namespace scanfilter::accuracy {

// A filter with one parameter set, scored.
struct ScoredFilter {
  RemovalScore score;
  double micros_per_scan = 0.0;
  std::size_t scans = 0;
};

// Makes a fresh filter for a log's sensor: multi-frame filters must not carry
// one log's history into the next.
using FilterFactory = std::function<std::unique_ptr<ScanFilter>(const SensorInfo&)>;

// Per log, per scan: the labels a filter gave.
using LogLabels = std::vector<std::vector<std::vector<std::uint8_t>>>;

// Runs a fresh filter per log over its scans in order, timing apply().
// labels_out, when given, receives each log's labels (for the figures).
ScoredFilter scoreFilter(const FilterFactory& make_filter, const std::vector<sim::LabelledLog>& logs,
                         LogLabels* labels_out = nullptr);

// The two-step filter as the harness runs it: the fast implementation, the
// `auto` values of `config` filled from the sensor.
std::unique_ptr<ScanFilter> makeTwoStepFilter(const FilterConfig& config, const SensorInfo& sensor);

// scoreFilter of makeTwoStepFilter(config, each log's sensor).
ScoredFilter scoreFilter(const FilterConfig& config, const std::vector<sim::LabelledLog>& logs,
                         LogLabels* labels_out = nullptr);

}  // namespace scanfilter::accuracy
