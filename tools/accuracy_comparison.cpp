#include "accuracy_comparison.hpp"

#include <chrono>

namespace scanfilter::cli {

ScoredFilter scoreFamily(const FilterFamily& family, const ParamValues& values,
                         const std::vector<sim::LabelledLog>& logs,
                         std::vector<std::vector<std::vector<std::uint8_t>>>* labels_out) {
  ScoredFilter out;
  std::chrono::duration<double> elapsed{0};
  std::vector<std::uint8_t> labels;
  for (const auto& log : logs) {
    auto filter = family.build(values, log.sensor);
    if (labels_out) labels_out->emplace_back();
    for (const auto& scan : log.scans) {
      labels.resize(scan.size());
      const auto start = std::chrono::steady_clock::now();
      filter->apply(scan, log.sensor, labels);
      elapsed += std::chrono::steady_clock::now() - start;
      out.score.add(scan, labels);
      if (labels_out) labels_out->back().push_back(labels);
      ++out.scans;
    }
  }
  out.micros_per_scan = out.scans ? 1e6 * elapsed.count() / static_cast<double>(out.scans) : 0.0;
  return out;
}

TunedFamily tuneFamily(const FilterFamily& family, const std::vector<sim::LabelledLog>& tune_logs,
                       std::size_t budget) {
  TunedFamily out;
  out.family = &family;
  const auto points = sweepPoints(family, budget);
  out.defaults = points.front();
  out.tuned_objective = -1.0;
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

}  // namespace scanfilter::cli
