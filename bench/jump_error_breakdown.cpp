// Where step 1 errs, by scene (seed 2, shipped defaults): missed jump points
// by their distance from the nearest true surface, and valid points deleted as
// jump points by range and by whether a beam without a return lies within two
// beams (a cluster cut short by the range limit or a dropout).
//   build/bench/jump_error_breakdown [--seed 2]
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_checks.hpp"
#include "scanfilter/accuracy/filter_score.hpp"
#include "scanfilter/accuracy/labelled_logs.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sim/ray_caster.hpp"

using namespace scanfilter;

namespace {

constexpr double kDistanceBucket = 0.05;  // m
constexpr int kDistanceBuckets = 6;       // the last one collects everything beyond
constexpr int kRangeBuckets = 6;          // 1 m each, the last one collects the rest
constexpr int kGapReach = 2;              // beams either side searched for a no-return

bool nearNoReturn(const Scan& scan, std::size_t i) {
  const auto n = static_cast<long>(scan.size());
  for (long k = -kGapReach; k <= kGapReach; ++k)
    if (!scan.hasReturn(static_cast<std::size_t>(((static_cast<long>(i) + k) % n + n) % n))) return true;
  return false;
}

void printRow(const char* what, const long (&counts)[kRangeBuckets > kDistanceBuckets ? kRangeBuckets : kDistanceBuckets],
              int buckets) {
  std::printf("  %-34s", what);
  for (int b = 0; b < buckets; ++b) std::printf(" %6ld", counts[b]);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seed = 2;
  CLI::App app{"Where step 1 errs, by scene: missed jump points by distance from the surface, false deletions by "
               "range"};
  app.add_option("--seed", seed, "simulator seed of the scenes")->capture_default_str()->check(bench::kSeedCheck);
  CLI11_PARSE(app, argc, argv);

  for (const auto& name : sim::builtinSceneNames()) {
    const sim::Scene scene = sim::findScene(name);
    const sim::RayCaster caster(scene);
    const auto log = accuracy::simulateScene(name, seed);
    accuracy::LogLabels log_labels;
    accuracy::scoreFilter(FilterConfig{}, {log}, &log_labels);
    long missed_by_distance[kRangeBuckets] = {}, deleted_by_range[kRangeBuckets] = {},
         deleted_near_gap_by_range[kRangeBuckets] = {}, found_near_gap_by_range[kRangeBuckets] = {};
    std::vector<Eigen::Vector2d> points;
    for (std::size_t s = 0; s < log.scans.size(); ++s) {
      const Scan& scan = log.scans[s];
      const std::vector<std::uint8_t>& labels = log_labels.front()[s];
      worldPoints(scan, log.sensor, points);
      for (std::size_t i = 0; i < scan.size(); ++i) {
        if (!scan.hasReturn(i)) continue;
        const bool truth_jump = scan.truth[i] == static_cast<std::uint8_t>(PointCode::kJump);
        const bool truth_valid = scan.truth[i] == static_cast<std::uint8_t>(PointCode::kValid);
        const bool labelled_jump = labels[i] == static_cast<std::uint8_t>(PointCode::kJump);
        const int range_bucket = std::min(kRangeBuckets - 1, static_cast<int>(scan.ranges[i]));
        if (truth_jump && !labelled_jump) {
          const double off = caster.distanceToSurface(points[i]);
          ++missed_by_distance[std::min(kDistanceBuckets - 1, static_cast<int>(off / kDistanceBucket))];
        }
        if (truth_valid && labelled_jump) {
          ++deleted_by_range[range_bucket];
          deleted_near_gap_by_range[range_bucket] += nearNoReturn(scan, i);
        }
        if (truth_jump && labelled_jump) found_near_gap_by_range[range_bucket] += nearNoReturn(scan, i);
      }
    }
    std::printf("%s (seed %llu)\n", name.c_str(), static_cast<unsigned long long>(seed));
    std::printf("  %-34s  0-5cm 5-10cm 10-15  15-20  20-25   25cm+\n", "jump points missed, off surface:");
    printRow("", missed_by_distance, kDistanceBuckets);
    std::printf("  %-34s    0-1m   1-2m   2-3m   3-4m   4-5m   5m+\n", "by range:");
    printRow("valid deleted as jump", deleted_by_range, kRangeBuckets);
    printRow("  of which near a no-return", deleted_near_gap_by_range, kRangeBuckets);
    printRow("jump points found near a no-return", found_near_gap_by_range, kRangeBuckets);
  }
  return 0;
}
