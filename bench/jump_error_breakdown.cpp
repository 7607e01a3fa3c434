// Where step 1 errs, by scene (seed 2, shipped defaults): missed jump points
// by their distance from the nearest true surface, and valid points deleted as
// jump points by range and by whether a beam without a return lies within two
// beams (a cluster cut short by the range limit or a dropout), and the missed
// ones by the shape of their neighbourhood and by which step kept them.
//   build/bench/jump_error_breakdown [--seed 2] [--sensor triangulation]
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_checks.hpp"
#include "scanfilter/accuracy/filter_score.hpp"
#include "scanfilter/accuracy/labelled_logs.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sim/ray_caster.hpp"
#include "scanfilter/sim/sensor_preset.hpp"

using namespace scanfilter;

namespace {

constexpr double kDistanceBucket = 0.05;  // m
constexpr int kDistanceBuckets = 6;       // the last one collects everything beyond
constexpr int kRangeBuckets = 6;          // 1 m each, the last one collects the rest
constexpr int kGapReach = 2;              // beams either side searched for a no-return

std::size_t wrapped(const Scan& scan, std::size_t i, long offset) {
  const auto n = static_cast<long>(scan.size());
  return static_cast<std::size_t>(((static_cast<long>(i) + offset) % n + n) % n);
}

bool nearNoReturn(const Scan& scan, std::size_t i) {
  for (long k = -kGapReach; k <= kGapReach; ++k)
    if (!scan.hasReturn(wrapped(scan, i, k))) return true;
  return false;
}

// Where a missed jump point stands against its two neighbouring beams, each
// farther (or without a return), nearer, or level within the off-surface
// tolerance: in front of both is what keep_foreground_clusters keeps, between
// a nearer and a farther one is a trail from an edge to its background.
enum Shape { kInFront, kBetween, kBehind, kLevel, kShapes };
constexpr const char* kShapeNames[kShapes] = {"in front of both", "between", "behind both", "level with one"};

Shape shapeOf(const Scan& scan, std::size_t i, double tolerance) {
  int farther = 0, nearer = 0;
  for (long side : {-1L, 1L}) {
    const std::size_t j = wrapped(scan, i, side);
    if (!scan.hasReturn(j) || scan.ranges[j] > scan.ranges[i] + tolerance) ++farther;
    else if (scan.ranges[j] < scan.ranges[i] - tolerance) ++nearer;
  }
  if (farther == 2) return kInFront;
  if (nearer == 2) return kBehind;
  if (farther + nearer == 2) return kBetween;
  return kLevel;
}

using Row = long[kRangeBuckets > kDistanceBuckets ? kRangeBuckets : kDistanceBuckets];

void printRow(const char* what, const Row& counts, int buckets) {
  std::printf("  %-34s", what);
  for (int b = 0; b < buckets; ++b) std::printf(" %6ld", counts[b]);
  std::printf("\n");
}

void breakdown(const std::string& name, const std::string& sensor, std::uint64_t seed) {
  const sim::Scene scene = sim::sceneWithSensor(name, sensor);
  const sim::RayCaster caster(scene);  // keeps a reference to the scene
  accuracy::SceneVariant variant;
  variant.sensor = sensor;
  const auto log = accuracy::simulateScene(name, seed, 0, variant);
  accuracy::LogLabels both_steps, step_one;
  accuracy::scoreFilter(FilterConfig{}, {log}, &both_steps);
  FilterConfig step_one_only;
  step_one_only.params.penetration_enabled = false;
  accuracy::scoreFilter(step_one_only, {log}, &step_one);
  const JumpFilterParams jump = FilterConfig{}.resolve(log.sensor).jump;

  Row missed_by_distance = {}, deleted_by_range = {}, deleted_near_gap_by_range = {}, found_near_gap_by_range = {};
  long missed_by_shape[2][kShapes] = {};  // [kept by step 1, restored by step 2][shape]
  std::vector<Eigen::Vector2d> points;
  for (std::size_t s = 0; s < log.scans.size(); ++s) {
    const Scan& scan = log.scans[s];
    const std::vector<std::uint8_t>& labels = both_steps.front()[s];
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
        const bool step_one_removed = step_one.front()[s][i] == static_cast<std::uint8_t>(PointCode::kJump);
        ++missed_by_shape[step_one_removed ? 1 : 0][shapeOf(scan, i, offSurfaceTolerance(jump, scan.ranges[i]))];
      }
      if (truth_valid && labelled_jump) {
        ++deleted_by_range[range_bucket];
        deleted_near_gap_by_range[range_bucket] += nearNoReturn(scan, i);
      }
      if (truth_jump && labelled_jump) found_near_gap_by_range[range_bucket] += nearNoReturn(scan, i);
    }
  }
  std::printf("%s%s%s (seed %llu)\n", name.c_str(), sensor.empty() ? "" : ", sensor ", sensor.c_str(),
              static_cast<unsigned long long>(seed));
  std::printf("  %-34s  0-5cm 5-10cm 10-15  15-20  20-25   25cm+\n", "jump points missed, off surface:");
  printRow("", missed_by_distance, kDistanceBuckets);
  std::printf("  %-34s", "  by shape:");
  for (const char* shape : kShapeNames) std::printf(" %16s", shape);
  std::printf("\n");
  for (int step = 0; step < 2; ++step) {
    std::printf("  %-34s", step == 0 ? "    kept by step 1" : "    removed by 1, restored by 2");
    for (long c : missed_by_shape[step]) std::printf(" %16ld", c);
    std::printf("\n");
  }
  std::printf("  %-34s    0-1m   1-2m   2-3m   3-4m   4-5m   5m+\n", "by range:");
  printRow("valid deleted as jump", deleted_by_range, kRangeBuckets);
  printRow("  of which near a no-return", deleted_near_gap_by_range, kRangeBuckets);
  printRow("jump points found near a no-return", found_near_gap_by_range, kRangeBuckets);
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seed = 2;
  std::string sensor;
  CLI::App app{"Where step 1 errs, by scene: missed jump points by distance from the surface and by the shape of "
               "their neighbourhood, false deletions by range"};
  app.add_option("--seed", seed, "simulator seed of the scenes")->capture_default_str()->check(bench::kSeedCheck);
  app.add_option("--sensor", sensor, "sensor preset (tof, triangulation) or file; default: each scene's own");
  CLI11_PARSE(app, argc, argv);
  for (const auto& name : sim::builtinSceneNames()) breakdown(name, sensor, seed);
  return 0;
}
