// Time per frame of each filter, fast vs reference (Google Benchmark).
//   build/bench/filter_bench --benchmark_min_time=0.2
// Jump filter: one simulated hall frame at 360, 1,080 and 3,600 beams.
// Penetration filter: one frame judged against a cache that holds every frame
// of a tour of 100 m² or 1,000 m² of rooms (T_max = ∞), so the reference's
// obstacle set grows with the area while the fast beam walk should not. The
// judged frame is taken in the corner room both areas share.
// Step 2 as a service runs it: every frame of a hall tour through apply()
// (expiry, alignment, judging, caching) at 360 and 3,600 beams, with the
// CPU caches warm or cold (64 MB of other data read between frames, as the
// other processes and the 25 ms between scans leave them).
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "scanfilter/filter_config.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/off_surface_check.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/range_noise_estimate.hpp"
#include "scanfilter/sim/scan_simulator.hpp"
#include "scanfilter/sim/sensor_preset.hpp"

using namespace scanfilter;

namespace {

constexpr double kRoomSide = 5.0;
constexpr double kDoorWidth = 1.0;
// The stream benchmark's tour (frames), and what is read between its frames
// to leave the caches cold: twice the L3 here (32 MB, shared with whatever
// else runs on the host; in the services the scans come 25 ms apart).
constexpr std::size_t kStreamFrames = 400;
constexpr std::size_t kStreamWarmFrames = 60;  // past min_frames and max_cache_frames (40)
constexpr std::size_t kEvictionBytes = 64u << 20;

Scan simulatedFrame(sim::Scene scene, int beams, int frame) {
  scene.lidar.beams = beams;
  sim::ScanSimulator simulator(std::move(scene), 1);
  ScanRecord record;
  for (int k = 0; k <= frame; ++k) simulator.next(record);
  return record.scan;
}

// A grid of square rooms with a door in the middle of every inner wall and a
// serpentine tour through all of them.
sim::Scene roomGrid(int rooms_x, int rooms_y) {
  sim::Scene scene = sim::findScene("hall");  // the hall's sensor and lidar model
  scene.segments.clear();
  scene.legs.clear();
  const double w = rooms_x * kRoomSide, h = rooms_y * kRoomSide, half_door = kDoorWidth / 2;
  auto wall = [&](Eigen::Vector2d a, Eigen::Vector2d b) { scene.segments.push_back({a, b, sim::Material::kRough}); };
  wall({0, 0}, {w, 0});
  wall({w, 0}, {w, h});
  wall({w, h}, {0, h});
  wall({0, h}, {0, 0});
  for (int i = 1; i < rooms_x; ++i)
    for (int j = 0; j < rooms_y; ++j) {
      const double x = i * kRoomSide, yc = (j + 0.5) * kRoomSide;
      wall({x, j * kRoomSide}, {x, yc - half_door});
      wall({x, yc + half_door}, {x, (j + 1) * kRoomSide});
    }
  for (int j = 1; j < rooms_y; ++j)
    for (int i = 0; i < rooms_x; ++i) {
      const double y = j * kRoomSide, xc = (i + 0.5) * kRoomSide;
      wall({i * kRoomSide, y}, {xc - half_door, y});
      wall({xc + half_door, y}, {(i + 1) * kRoomSide, y});
    }
  scene.trajectory.waypoints.clear();
  for (int j = 0; j < rooms_y; ++j)
    for (int k = 0; k < rooms_x; ++k) {
      const int i = j % 2 == 0 ? k : rooms_x - 1 - k;
      scene.trajectory.waypoints.push_back({(i + 0.5) * kRoomSide, (j + 0.5) * kRoomSide});
    }
  scene.trajectory.speed = 0.5;
  return scene;
}

// A penetration filter whose cache holds a whole tour, and the frame to judge.
struct ExploredState {
  std::unique_ptr<PenetrationFilter> filter;
  Scan frame;
  SensorInfo sensor;
  std::size_t obstacle_cells = 0;
};

ExploredState& explored(Implementation impl, int area_m2, int beams) {
  static std::map<std::tuple<Implementation, int, int>, ExploredState> cache;
  auto& state = cache[{impl, area_m2, beams}];
  if (state.filter) return state;
  const int rooms = static_cast<int>(std::lround(std::sqrt(area_m2 / (kRoomSide * kRoomSide))));
  sim::Scene scene = roomGrid(rooms, rooms);
  scene.odometry = {};  // true poses: a whole tour's drift would leave the judged frame fitting nothing
  PenetrationFilterParams p;
  p.frame_lifetime = 1e9;
  p.max_cache_frames = 1u << 30;
  // What is timed is the judging, reference against fast; the frame
  // alignment before it is shared code, the same for both (its cost: the
  // per-scan section of docs/performance.md).
  p.alignment.enabled = false;
  // Nor the surface memory: the same code in both (its cost: the stream
  // benchmark without it).
  p.surface_memory.lifetime = 0.0;
  state.filter = makePenetrationFilter(p, impl);
  sim::ScanSimulator simulator(scene, 1);
  state.sensor = simulator.header().sensor;
  ScanRecord record;
  std::vector<std::uint8_t> labels;
  while (simulator.next(record)) {
    labels.assign(record.scan.size(), static_cast<std::uint8_t>(PointCode::kValid));
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (!record.scan.hasReturn(i)) labels[i] = static_cast<std::uint8_t>(PointCode::kNoReturn);
    state.filter->apply(record.scan, state.sensor, labels);
  }
  // The judged frame: the tour's first pose, in the corner room that both
  // areas share, so the two areas judge the same geometry.
  state.frame = simulatedFrame(scene, beams, 0);
  state.filter->grid().forEachCellAbove(p.obstacle_threshold, [&](CellIndex, int) { ++state.obstacle_cells; });
  return state;
}

// The paper's clustering (eq. 5-7): the off-surface check and the noise
// estimate are off here; each is the same O(N) pass in both implementations
// and has its own benchmark.
void BM_JumpFilter(benchmark::State& state, Implementation impl) {
  const int beams = static_cast<int>(state.range(0));
  const sim::Scene hall = sim::findScene("hall");
  const Scan scan = simulatedFrame(hall, beams, 200);
  JumpFilterParams params;
  params.off_surface_check = false;
  params.noise_estimate = false;
  auto filter = makeJumpFilter(params, impl);
  std::vector<std::uint8_t> labels(scan.size());
  for (auto _ : state) {
    filter->apply(scan, hall.sensor, labels);
    benchmark::DoNotOptimize(labels.data());
  }
  state.counters["beams"] = beams;
}

// One simulated hall frame (frame 200) and its points in the sensor frame:
// what the per-scan passes of step 1 below run on.
struct HallFrame {
  sim::Scene hall = sim::findScene("hall");
  Scan scan;
  std::vector<Eigen::Vector2d> points;

  explicit HallFrame(int beams) : scan(simulatedFrame(hall, beams, 200)) {
    BeamDirectionTable directions;
    sensorFramePoints(scan, hall.sensor, directions, points);
  }
};

// The range-noise estimate alone: one scan's residuals added and the model
// refitted, on the same frame.
void BM_RangeNoiseEstimate(benchmark::State& state) {
  const int beams = static_cast<int>(state.range(0));
  const HallFrame frame(beams);
  JumpFilterParams params;
  params.d_max = frame.hall.sensor.range_max;
  RangeNoiseEstimate estimate(params);
  for (auto _ : state) {
    estimate.add(frame.points, frame.scan.ranges, true);
    benchmark::DoNotOptimize(estimate.model());
  }
  state.counters["beams"] = beams;
}

// The off-surface check alone, on the same frame (every point valid to start).
void BM_OffSurfaceCheck(benchmark::State& state) {
  const int beams = static_cast<int>(state.range(0));
  const HallFrame frame(beams);
  OffSurfaceCheck check{JumpFilterParams{}};
  std::vector<std::uint8_t> labels(frame.scan.size());
  const std::vector<std::uint8_t> none_spared(frame.scan.size(), 0);
  for (auto _ : state) {
    std::fill(labels.begin(), labels.end(), static_cast<std::uint8_t>(PointCode::kValid));
    check.apply(frame.points, frame.scan.ranges, isFullTurn(frame.scan), none_spared, labels);
    benchmark::DoNotOptimize(labels.data());
  }
  state.counters["beams"] = beams;
}

void BM_PenetrationJudge(benchmark::State& state, Implementation impl) {
  const int beams = static_cast<int>(state.range(0));
  const int area = static_cast<int>(state.range(1));
  ExploredState& s = explored(impl, area, beams);
  std::vector<std::uint8_t> labels(s.frame.size());
  for (auto _ : state) {
    for (std::size_t i = 0; i < labels.size(); ++i)
      labels[i] = static_cast<std::uint8_t>(s.frame.hasReturn(i) ? PointCode::kValid : PointCode::kNoReturn);
    s.filter->judge(s.frame, s.sensor, labels);
    benchmark::DoNotOptimize(labels.data());
  }
  state.counters["obstacle_cells"] = static_cast<double>(s.obstacle_cells);
  state.counters["grid_MB"] = static_cast<double>(s.filter->grid().memoryBytes()) / 1e6;
}

// Frames of the hall at `beams` with step 1's labels (what step 2 is given
// in the pipeline), and the resolved step-2 parameters for that sensor
// (obs_th follows the angular step), built once per beam count.
struct HallTour {
  SensorInfo sensor;
  PenetrationFilterParams params;
  std::vector<Scan> frames;
  std::vector<std::vector<std::uint8_t>> step1_labels;
};

const HallTour& hallTour(int beams) {
  static std::map<int, HallTour> tours;
  HallTour& tour = tours[beams];
  if (!tour.frames.empty()) return tour;
  sim::ScanSimulator simulator(sim::sceneWithSensor("hall", "", beams), 2);
  tour.sensor = simulator.header().sensor;
  const TwoStepFilterParams params = FilterConfig{}.resolve(tour.sensor);
  tour.params = params.penetration;
  auto jump = makeJumpFilter(params.jump, Implementation::kFast);
  ScanRecord record;
  while (tour.frames.size() < kStreamFrames && simulator.next(record)) {
    std::vector<std::uint8_t> labels(record.scan.size());
    jump->apply(record.scan, tour.sensor, labels);
    tour.frames.push_back(record.scan);
    tour.step1_labels.push_back(std::move(labels));
  }
  return tour;
}

// Reads `kEvictionBytes` so that what step 2 left in the caches is gone.
void evictCaches() {
  static std::vector<std::uint64_t> other(kEvictionBytes / sizeof(std::uint64_t), 1);
  std::uint64_t sum = 0;
  for (std::size_t i = 0; i < other.size(); i += 8) sum += other[i];  // one read a cache line
  benchmark::DoNotOptimize(sum);
}

void BM_PenetrationStream(benchmark::State& state) {
  const int beams = static_cast<int>(state.range(0));
  const bool cold = state.range(1) != 0;
  const HallTour& tour = hallTour(beams);
  PenetrationFilterParams params = tour.params;
  params.free_space_check = state.range(2) != 0;  // its cost: the same stream without it
  if (state.range(3) == 0) params.surface_memory.lifetime = 0.0;  // the memory's cost, likewise
  params.thin_object_check = state.range(4) != 0;                 // and the thin-object check's
  auto filter = makePenetrationFilter(params, Implementation::kFast);
  std::vector<std::uint8_t> labels;
  std::size_t next = 0;
  // Untimed: the warm-up frames and a full cache (the steady state a
  // service runs in), at the start and again after each lap of the tour.
  const auto fillCache = [&] {
    filter->reset();
    for (next = 0; next < kStreamWarmFrames; ++next) {
      labels = tour.step1_labels[next];
      filter->apply(tour.frames[next], tour.sensor, labels);
    }
  };
  fillCache();
  for (auto _ : state) {
    state.PauseTiming();
    if (next == tour.frames.size()) fillCache();
    labels = tour.step1_labels[next];
    if (cold) evictCaches();
    state.ResumeTiming();
    filter->apply(tour.frames[next++], tour.sensor, labels);
    benchmark::DoNotOptimize(labels.data());
  }
  state.counters["beams"] = beams;
}

}  // namespace

BENCHMARK_CAPTURE(BM_JumpFilter, reference, Implementation::kReference)->Arg(360)->Arg(1080)->Arg(3600)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_JumpFilter, fast, Implementation::kFast)->Arg(360)->Arg(1080)->Arg(3600)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RangeNoiseEstimate)->Arg(360)->Arg(1080)->Arg(3600)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OffSurfaceCheck)->Arg(360)->Arg(1080)->Arg(3600)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PenetrationJudge, reference, Implementation::kReference)
    ->ArgsProduct({{360, 1080, 3600}, {100, 1000}})->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_PenetrationJudge, fast, Implementation::kFast)
    ->ArgsProduct({{360, 1080, 3600}, {100, 1000}})->Unit(benchmark::kMicrosecond);
// The shipped step 2 warm and cold, and warm without the free-space check,
// without the surface memory or without the thin-object check.
BENCHMARK(BM_PenetrationStream)
    ->ArgNames({"beams", "cold", "free_space", "surface_memory", "thin_object"})
    ->Args({360, 0, 1, 1, 1})->Args({360, 1, 1, 1, 1})->Args({360, 0, 0, 1, 1})->Args({360, 0, 1, 0, 1})
    ->Args({360, 0, 1, 1, 0})
    ->Args({3600, 0, 1, 1, 1})->Args({3600, 1, 1, 1, 1})->Args({3600, 0, 0, 1, 1})->Args({3600, 0, 1, 0, 1})
    ->Args({3600, 0, 1, 1, 0})
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
