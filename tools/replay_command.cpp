#include <chrono>
#include <iomanip>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "score_report.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/removal_score.hpp"
#include "scanfilter/scan_log_writer.hpp"
#include "scanfilter/scan_renderer.hpp"
#include "scanfilter/two_step_filter.hpp"

namespace scanfilter::cli {
namespace {

// "LABEL: sigma(d) = B mm + Q mm/m^2 * d^2NOTE", in millimetres to three decimals.
void printNoiseModel(const char* label, const RangeNoiseModel& noise, const char* note) {
  const std::ios_base::fmtflags flags = std::cout.flags();
  const std::streamsize precision = std::cout.precision();
  std::cout << label << ": sigma(d) = " << std::fixed << std::setprecision(3) << 1e3 * noise.base << " mm + "
            << 1e3 * noise.quadratic << " mm/m^2 * d^2" << note << "\n";
  std::cout.flags(flags);
  std::cout.precision(precision);
}

}  // namespace

int runReplay(const ReplayOptions& options) {
  ScanSourceOptions source_options;
  source_options.carmen_range_max = options.carmen_range_max;
  auto source = openScanSource(options.input, source_options);
  const FilterConfig config = options.config.empty() ? FilterConfig{} : loadFilterConfig(options.config);
  const SensorInfo& sensor = source->header().sensor;
  TwoStepFilter filter(config.resolve(sensor), options.reference ? Implementation::kReference : Implementation::kFast);

  std::optional<ScanLogWriter> writer;
  if (!options.output.empty()) writer.emplace(options.output, source->header());
  ScanRenderer renderer;
  RemovalScore score;
  ScanRecord record;
  std::chrono::duration<double> filter_time{0};
  while (source->next(record)) {
    record.scan.labels.resize(record.scan.size());
    const auto start = std::chrono::steady_clock::now();
    filter.apply(record.scan, sensor, record.scan.labels);
    filter_time += std::chrono::steady_clock::now() - start;
    score.add(record.scan, record.scan.labels);
    if (writer) writer->write(record);
    if (!options.render.empty()) renderer.add(record.scan, sensor, record.scan.labels);
  }
  if (writer) writer->close();
  if (!options.render.empty()) renderer.save(options.render, {.title = options.input});
  if (options.quiet) return 0;

  std::cout << "input: " << options.input << " (" << (options.reference ? "reference" : "fast")
            << " implementation)\n";
  printScoreReport(std::cout, score);
  if (score.frames() > 0)
    std::cout << "filter time: " << 1e3 * filter_time.count() / static_cast<double>(score.frames())
              << " ms per scan\n";
  if (config.params.jump_enabled)
    printNoiseModel("step 1 range noise", filter.jump().noiseModel(),
                    config.params.jump.noise_estimate ? " (each term the larger of measured and configured)" : "");
  const PenetrationFilterParams& step2 = config.params.penetration;
  if (config.params.penetration_enabled && step2.rescue_persistent_points && step2.evidence_noise_sigmas > 0.0)
    printNoiseModel("step 2 range noise (evidence radius)", filter.penetration().evidenceNoise(), " (measured alone)");
  if (config.params.penetration_enabled && config.params.penetration.alignment.enabled)
    std::cout << "step 2 frames not judged (did not fit the cache): " << filter.penetration().unalignedFrames()
              << " of " << score.frames() << "\n";
  if (filter.penetration().resetCount() > 0)
    std::cout << "penetration cache resets on pose jumps: " << filter.penetration().resetCount() << "\n";
  if (writer) std::cout << "labelled log: " << options.output << "\n";
  if (!options.render.empty()) std::cout << "picture: " << options.render << "\n";
  return 0;
}

}  // namespace scanfilter::cli
