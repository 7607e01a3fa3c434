#include "scanfilter/accuracy/filter_score.hpp"

#include <chrono>

#include "scanfilter/two_step_filter.hpp"

namespace scanfilter::accuracy {

namespace {
constexpr double kMicrosPerSecond = 1e6;
}  // namespace

ScoredFilter scoreFilter(const FilterFactory& make_filter, const std::vector<sim::LabelledLog>& logs,
                         LogLabels* labels_out) {
  ScoredFilter out;
  std::chrono::duration<double> elapsed{0};
  std::vector<std::uint8_t> labels;
  for (const auto& log : logs) {
    auto filter = make_filter(log.sensor);
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
  out.micros_per_scan = out.scans ? kMicrosPerSecond * elapsed.count() / static_cast<double>(out.scans) : 0.0;
  return out;
}

std::unique_ptr<ScanFilter> makeTwoStepFilter(const FilterConfig& config, const SensorInfo& sensor) {
  return std::make_unique<TwoStepFilter>(config.resolve(sensor), Implementation::kFast);
}

ScoredFilter scoreFilter(const FilterConfig& config, const std::vector<sim::LabelledLog>& logs,
                         LogLabels* labels_out) {
  return scoreFilter([&config](const SensorInfo& sensor) { return makeTwoStepFilter(config, sensor); }, logs,
                     labels_out);
}

}  // namespace scanfilter::accuracy
