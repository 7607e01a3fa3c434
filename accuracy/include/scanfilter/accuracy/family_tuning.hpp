#pragma once
// Tuning a filter family with a sweep budget on tuning logs, and scoring one
// of its parameter sets: how `scanfilter bench-accuracy` gives every filter
// of the comparison the same chance.
#include <cstddef>
#include <vector>

#include "scanfilter/accuracy/filter_family.hpp"
#include "scanfilter/accuracy/filter_score.hpp"

namespace scanfilter::accuracy {

struct TunedFamily {
  const FilterFamily* family = nullptr;
  ParamValues defaults;
  ParamValues tuned;
  double tuned_objective = 0.0;  // artefact F1 on the tuning logs
  std::size_t evaluations = 0;
};

// Scores one parameter set of `family` over logs (see scoreFilter).
ScoredFilter scoreFamily(const FilterFamily& family, const ParamValues& values,
                         const std::vector<sim::LabelledLog>& logs, LogLabels* labels_out = nullptr);

// Tries `budget` grid points on the tuning logs; keeps the best artefact F1
// (earlier points win ties, so the defaults win a tie).
TunedFamily tuneFamily(const FilterFamily& family, const std::vector<sim::LabelledLog>& tune_logs,
                       std::size_t budget);

}  // namespace scanfilter::accuracy
