#include "scanfilter/accuracy/family_tuning.hpp"

namespace scanfilter::accuracy {

ScoredFilter scoreFamily(const FilterFamily& family, const ParamValues& values,
                         const std::vector<sim::LabelledLog>& logs, LogLabels* labels_out) {
  return scoreFilter([&](const SensorInfo& sensor) { return family.build(values, sensor); }, logs, labels_out);
}

TunedFamily tuneFamily(const FilterFamily& family, const std::vector<sim::LabelledLog>& tune_logs,
                       std::size_t budget) {
  TunedFamily out;
  out.family = &family;
  const auto points = sweepPoints(family, budget);
  out.defaults = points.front();
  out.tuned_objective = -1.0;  // below any F1, so the first point is kept
  for (const auto& point : points) {
    const double objective = scoreFamily(family, point, tune_logs).score.artefactF1();
    ++out.evaluations;
    if (objective > out.tuned_objective) {
      out.tuned_objective = objective;
      out.tuned = point;
    }
  }
  return out;
}

}  // namespace scanfilter::accuracy
