#include <array>
#include <cmath>
#include <iostream>
#include <numbers>

#include "commands.hpp"
#include "scanfilter/artefact_cause.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_source.hpp"

namespace scanfilter::cli {

int runInfo(const InfoOptions& options) {
  ScanSourceOptions source_options;
  source_options.carmen_range_max = options.carmen_range_max;
  auto source = openScanSource(options.input, source_options);
  const ScanLogHeader& h = source->header();
  std::size_t scans = 0, beams = 0, returns = 0, labelled = 0, with_truth = 0;
  Stamp first, last;
  double path = 0.0;
  std::size_t min_beams = SIZE_MAX, max_beams = 0;
  std::array<std::size_t, kPointCodeCount> label_counts{}, truth_counts{};
  std::array<std::size_t, kArtefactCauseCount> cause_counts{};
  Pose2 previous;
  ScanRecord record;
  while (source->next(record)) {
    const Scan& s = record.scan;
    if (scans == 0) first = s.stamp;
    else path += std::hypot(s.pose.x - previous.x, s.pose.y - previous.y);
    last = s.stamp;
    previous = s.pose;
    ++scans;
    beams += s.size();
    min_beams = std::min(min_beams, s.size());
    max_beams = std::max(max_beams, s.size());
    for (std::size_t i = 0; i < s.size(); ++i) returns += s.hasReturn(i);
    labelled += !s.labels.empty();
    for (auto code : s.labels) ++label_counts[code];
    for (auto code : s.truth) ++truth_counts[code];
    for (auto cause : s.truth_cause) ++cause_counts[cause];
    with_truth += !s.truth.empty();
  }
  std::cout << "file:      " << options.input << "\n"
            << "source:    " << h.source << "\n"
            << "sensor:    mount [" << h.sensor.mount.x << ", " << h.sensor.mount.y << ", " << h.sensor.mount.yaw
            << "], " << (h.sensor.direction == BeamDirection::kCcw ? "ccw" : "cw") << ", range "
            << h.sensor.range_min << "-" << h.sensor.range_max << " m, angular accuracy "
            << h.sensor.angular_accuracy_deg << " deg\n"
            << "scans:     " << scans << " (" << min_beams << "-" << max_beams << " beams)\n"
            << "duration:  " << last.secondsSince(first) << " s (" << first.toDecimal() << " to " << last.toDecimal()
            << "), path " << path << " m\n"
            << "stamps:    " << source->stampRegressions() << " earlier than the scan before (kept in file order), "
            << source->stampRepeats() << " equal to it\n"
            << "returns:   " << returns << " of " << beams << " beams\n"
            << "truth:     " << with_truth << " scans, labels: " << labelled << " scans\n";
  const auto counts = [](const char* title, const std::array<std::size_t, kPointCodeCount>& n) {
    std::cout << title;
    for (int c = 0; c < kPointCodeCount; ++c)
      std::cout << " " << pointCodeName(static_cast<PointCode>(c)) << "=" << n[static_cast<std::size_t>(c)];
    std::cout << "\n";
  };
  if (with_truth > 0) counts("truth by code:", truth_counts);
  if (labelled > 0) counts("labels:   ", label_counts);
  const auto count = [&](ArtefactCause c) { return cause_counts[static_cast<std::size_t>(c)]; };
  std::size_t with_cause = 0;
  for (ArtefactCause c : kEveryArtefactCause) with_cause += count(c);
  if (with_cause > 0) {
    std::cout << "truth by cause:";
    const char* separator = " ";
    for (ArtefactCause c : kEveryArtefactCause) {
      std::cout << separator << artefactCauseName(c) << "=" << count(c);
      separator = ", ";
    }
    std::cout << "\n";
  }
  return 0;
}

}  // namespace scanfilter::cli
