// Why step 2 misses what it misses, by scene (held-out seed, shipped
// defaults, true poses so that pose error is not one of the reasons): each
// simulated misdetected return (a ghost behind a mirror, a return through
// glass) that the filter keeps is put in the first class that explains it:
//   - not judged: the frame came before min_frames or did not fit the cache;
//   - labelled jump: removed, but as a jump point (by step 1 or by step 2's
//     free-space check);
//   - surface unseen: no cached cell within one cell of where the beam really
//     met the surface it went through holds more than obs_th returns (the
//     mirror or pane is rarely seen directly);
//   - just behind: the return lies within the own-surface margin of that
//     surface (own_surface_margin and _per_m; the grazing widening is not
//     counted here): the penetration model cannot tell it from the surface;
//   - other: the cells are there and far enough, yet not on both sides of
//     the beam within surface_gap.
// The surface-unseen returns are split once more by whether the run's valid
// returns had hit the surface there more than obs_th times at all (the
// cells within one cell of the crossing, true poses), and how long before:
// within 2 or 5 times T_max, earlier, or never. That bounds what a memory of
// surfaces longer than the cache could find
// (docs/accuracy-investigations.md, "Where step 2 loses, and what was tried").
// And by what the surface memory (Beyond the paper 24) held there when the
// frame was judged: a live segment confirmed as a pane or mirror, a live
// one not confirmed, only segments past their lifetime, or nothing.
//   build/bench/misdetected_error_breakdown [--seed 2] [--sensor triangulation] [--config variant.yaml]
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_checks.hpp"
#include "surface_history.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sim/ray_caster.hpp"
#include "scanfilter/sim/scan_simulator.hpp"
#include "scanfilter/sim/sensor_preset.hpp"
#include "scanfilter/two_step_filter.hpp"

using namespace scanfilter;

namespace {

enum Reason { kFound, kNotJudged, kLabelledJump, kSurfaceUnseen, kJustBehind, kOther, kReasons };
constexpr const char* kReasonNames[kReasons] = {"found",          "not judged",  "labelled jump",
                                                "surface unseen", "just behind", "other"};

// The most returns any cell within one cell of p holds in the cache.
int cachedReturnsNear(const PenetrationGrid& grid, const Eigen::Vector2d& p) {
  const CellIndex c = grid.cellOf(p);
  int most = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) most = std::max(most, grid.count({c.x + dx, c.y + dy}));
  return most;
}

// When the surface of a surface-unseen return had been hit more than obs_th
// times: the windows are multiples of T_max, the cache's own lifetime.
enum SeenBefore { kWithin2Tmax, kWithin5Tmax, kEarlier, kNever, kSeenBefore };
constexpr const char* kSeenBeforeNames[kSeenBefore] = {"within 2 T_max", "within 5 T_max", "earlier", "never"};
constexpr double kSeenBeforeWindows[] = {2.0, 5.0};  // in T_max

SeenBefore seenBefore(const bench::SurfaceHistory& history, const Eigen::Vector2d& p, double t,
                      const PenetrationFilterParams& pen) {
  if (history.mostHitsNear(p, t, kSeenBeforeWindows[0] * pen.frame_lifetime) > pen.obstacle_threshold)
    return kWithin2Tmax;
  if (history.mostHitsNear(p, t, kSeenBeforeWindows[1] * pen.frame_lifetime) > pen.obstacle_threshold)
    return kWithin5Tmax;
  const double whole_run_so_far = t + 1.0;  // a window that starts before the first scan
  if (history.mostHitsNear(p, t, whole_run_so_far) > pen.obstacle_threshold) return kEarlier;
  return kNever;
}

// What the surface memory held within kMemoryRadius of the crossing.
enum MemoryHeld { kLiveConfirmed, kLiveUnconfirmed, kExpired, kNothing, kMemoryHeld };
constexpr const char* kMemoryHeldNames[kMemoryHeld] = {"live, pane or mirror", "live, not confirmed",
                                                       "past its lifetime", "nothing"};
constexpr double kMemoryRadius = 0.10;  // m: two cells, the crossing's own and its neighbour's

MemoryHeld memoryHeld(const SurfaceMemory& memory, const Eigen::Vector2d& p, Stamp now) {
  const auto held = memory.heldNear(p, now, kMemoryRadius);
  if (!held) return kNothing;
  if (!held->alive) return kExpired;
  return held->pane_or_mirror ? kLiveConfirmed : kLiveUnconfirmed;
}

struct Counts {
  long by_reason[kReasons] = {};
  long unseen_by_when[kSeenBefore] = {};
  long unseen_by_memory[kMemoryHeld] = {};
  long total() const {
    long n = 0;
    for (long c : by_reason) n += c;
    return n;
  }
};

Counts breakdown(const std::string& scene_name, const std::string& sensor, std::uint64_t seed,
                 const FilterConfig& config) {
  sim::Scene scene = sim::sceneWithSensor(scene_name, sensor);
  scene.odometry = sim::OdometryDrift{};  // true poses
  const sim::RayCaster caster(scene);
  sim::ScanSimulator simulator(scene, seed);
  const SensorInfo& info = simulator.header().sensor;
  const TwoStepFilterParams params = config.resolve(info);
  TwoStepFilter filter(params, Implementation::kFast);
  const PenetrationFilterParams& pen = params.penetration;
  Counts counts;
  ScanRecord record;
  std::vector<std::uint8_t> labels;
  bench::SurfaceHistory history(pen.cell_size);
  std::optional<Stamp> first_stamp;
  while (simulator.next(record)) {
    const Scan& scan = record.scan;
    const Eigen::Vector2d origin = sensorOrigin(scan.pose, info.mount);
    if (!first_stamp) first_stamp = scan.stamp;
    const double t = scan.stamp.secondsSince(*first_stamp);
    // What the cache holds before this frame goes in.
    std::vector<int> near_surface(scan.size(), -1);
    std::vector<double> behind(scan.size(), 0.0);
    std::vector<SeenBefore> seen(scan.size(), kNever);
    std::vector<MemoryHeld> held(scan.size(), kNothing);
    for (std::size_t i = 0; i < scan.size(); ++i) {
      if (scan.truth[i] != static_cast<std::uint8_t>(PointCode::kMisdetected)) continue;
      const double a = beamWorldAngle(scan, info, i);
      const auto hit = caster.cast(origin, {std::cos(a), std::sin(a)}, info.range_max);
      if (!hit) continue;
      near_surface[i] = cachedReturnsNear(filter.penetration().grid(), hit->point);
      seen[i] = seenBefore(history, hit->point, t, pen);
      held[i] = memoryHeld(filter.penetration().surfaceMemory(), hit->point, scan.stamp);
      behind[i] = scan.ranges[i] - hit->range;
    }
    const std::size_t unaligned_before = filter.penetration().unalignedFrames();
    const bool warm = filter.penetration().framesSinceReset() + 1 >= static_cast<std::size_t>(pen.min_frames);
    labels.assign(scan.size(), 0);
    filter.apply(scan, info, labels);
    const bool judged = warm && filter.penetration().unalignedFrames() == unaligned_before;
    for (std::size_t i = 0; i < scan.size(); ++i) {
      if (near_surface[i] < 0) continue;
      Reason r = kOther;
      if (labels[i] == static_cast<std::uint8_t>(PointCode::kMisdetected)) r = kFound;
      else if (labels[i] == static_cast<std::uint8_t>(PointCode::kJump)) r = kLabelledJump;
      else if (!judged) r = kNotJudged;
      else if (near_surface[i] <= pen.obstacle_threshold) {
        r = kSurfaceUnseen;
        ++counts.unseen_by_when[seen[i]];
        ++counts.unseen_by_memory[held[i]];
      }
      else if (behind[i] < pen.own_surface_margin + pen.own_surface_margin_per_m * scan.ranges[i]) r = kJustBehind;
      ++counts.by_reason[r];
    }
    for (std::size_t i = 0; i < scan.size(); ++i) {
      if (scan.truth[i] != static_cast<std::uint8_t>(PointCode::kValid)) continue;
      const double a = beamWorldAngle(scan, info, i);
      history.add(origin + scan.ranges[i] * Eigen::Vector2d(std::cos(a), std::sin(a)), t);
    }
  }
  return counts;
}

// One table per scene of how its surface-unseen returns split: `names` the
// columns, `split` the counts in the same order.
template <std::size_t N>
void printUnseenSplit(const std::vector<std::pair<std::string, Counts>>& scenes, const char* const (&names)[N],
                      long (Counts::*split)[N]) {
  std::printf("| scene | surface unseen |");
  for (const char* name : names) std::printf(" %s |", name);
  std::printf("\n|---|---|");
  for (std::size_t k = 0; k < N; ++k) std::printf("---|");
  std::printf("\n");
  for (const auto& [name, c] : scenes) {
    const long unseen = c.by_reason[kSurfaceUnseen];
    std::printf("| %s | %ld |", name.c_str(), unseen);
    for (long n : c.*split) std::printf(" %ld (%.0f %%) |", n, unseen > 0 ? 100.0 * n / unseen : 0.0);
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t seed = 2;
  std::string sensor;
  std::string config_path;
  CLI::App app{"Why step 2 misses the misdetected returns it misses, by scene (true poses, shipped defaults)"};
  app.add_option("--seed", seed, "simulator seed of the scenes")->capture_default_str()->check(bench::kSeedCheck);
  app.add_option("--sensor", sensor, "sensor preset (tof, triangulation) or file; default: each scene's own");
  app.add_option("--config", config_path, "filter config file (a variant); default: the shipped defaults")
      ->check(CLI::ExistingFile);
  CLI11_PARSE(app, argc, argv);
  const FilterConfig config = config_path.empty() ? FilterConfig{} : loadFilterConfig(config_path);

  std::printf("| scene | misdetected returns |");
  for (const char* name : kReasonNames) std::printf(" %s |", name);
  std::printf("\n|---|---|");
  for (int r = 0; r < kReasons; ++r) std::printf("---|");
  std::printf("\n");
  std::vector<std::pair<std::string, Counts>> scenes;
  for (const auto& name : sim::builtinSceneNames()) {
    const Counts c = breakdown(name, sensor, seed, config);
    std::printf("| %s | %ld |", name.c_str(), c.total());
    for (long n : c.by_reason) std::printf(" %ld (%.0f %%) |", n, c.total() > 0 ? 100.0 * n / c.total() : 0.0);
    std::printf("\n");
    std::fflush(stdout);
    scenes.emplace_back(name, c);
  }
  std::printf("\nsurface unseen: when the run's valid returns had hit that surface more than obs_th times\n\n");
  printUnseenSplit(scenes, kSeenBeforeNames, &Counts::unseen_by_when);
  std::printf("\nsurface unseen: what the surface memory held within %.2f m of the crossing\n\n", kMemoryRadius);
  printUnseenSplit(scenes, kMemoryHeldNames, &Counts::unseen_by_memory);
  return 0;
}
