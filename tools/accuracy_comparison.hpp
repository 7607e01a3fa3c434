#pragma once
// The work of `scanfilter bench-accuracy`: tune every filter of the
// comparison with the same sweep budget on tuning logs, score the chosen
// parameters (and the published defaults) on other logs, and report.
#include <string>
#include <vector>

#include "comparison_filters.hpp"
#include "scanfilter/removal_score.hpp"
#include "scanfilter/sim/labelled_log.hpp"

namespace scanfilter::cli {

// A filter with one parameter set, scored.
struct ScoredFilter {
  RemovalScore score;
  double micros_per_scan = 0.0;
  std::size_t scans = 0;
};

struct TunedFamily {
  const FilterFamily* family = nullptr;
  ParamValues defaults;
  ParamValues tuned;
  double tuned_objective = 0.0;  // artefact F1 on the tuning logs
  std::size_t evaluations = 0;
};

// Runs one parameter set over logs (a fresh filter per log), timing apply().
// labels_out, when given, receives each log's labels (for the figures).
ScoredFilter scoreFamily(const FilterFamily& family, const ParamValues& values,
                         const std::vector<sim::LabelledLog>& logs,
                         std::vector<std::vector<std::vector<std::uint8_t>>>* labels_out = nullptr);

// Tries `budget` grid points on the tuning logs; keeps the best artefact F1
// (earlier points win ties, so the defaults win a tie).
TunedFamily tuneFamily(const FilterFamily& family, const std::vector<sim::LabelledLog>& tune_logs,
                       std::size_t budget);

}  // namespace scanfilter::cli
