#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace scanfilter::cli {

struct SimulateOptions {
  std::string scene = "hall";
  std::string sensor;  // preset name or file; empty: the scene's own sensor
  int beams = 0;       // 0: the sensor's own
  bool true_poses = false;  // log the true poses instead of drifting odometry
  std::uint64_t seed = 1;
  std::string output;
  int max_frames = 0;  // 0: the whole trajectory
};

struct ReplayOptions {
  std::string input;
  std::string output;  // empty: no log written
  std::string config;  // empty: built-in defaults
  bool reference = false;
  std::string render;  // PNG path, empty: none
  double carmen_range_max = 80.0;
  bool quiet = false;
};

struct RenderOptionsCli {
  std::string input;
  std::string output;
  std::string title;
  int pixels = 800;
  int first_frame = 0;
  int frames = 0;  // 0: all
};

struct InfoOptions {
  std::string input;
  double carmen_range_max = 80.0;
};

struct DiffOptions {
  std::string first;
  std::string second;
};

struct MapOptions {
  std::string input;
  std::string output;  // base path: BASE.pgm, BASE.yaml, BASE.png, BASE.logodds
  std::string config;
  double resolution = 0.05;
  bool unfiltered = false;
  double carmen_range_max = 80.0;
};

struct BenchAccuracyOptions {
  std::vector<std::string> logs;       // labelled logs scored on (empty: built-in scenes at test_seeds)
  std::vector<std::string> tune_logs;  // labelled logs tuned on (empty: built-in scenes at tune_seed)
  std::uint64_t tune_seed = 1;
  std::vector<std::uint64_t> test_seeds = {2, 3};
  std::size_t budget = 24;  // sweep evaluations per filter
  std::string config;       // our filter's config (empty: built-in defaults)
  std::string output_dir;   // figures and accuracy-comparison.md; empty: stdout only
  bool robustness = true;
  int max_frames = 0;  // per simulated log, 0: whole trajectory
  std::string sensor;  // sensor preset of the simulated logs; empty: each scene's own
};

struct ReportRealOptions {
  std::vector<std::string> logs;  // CARMEN, Mines URG-04LX or scan logs
  std::string config;             // filter config (empty: built-in defaults)
  std::string literal_config;     // the paper-literal config, also scored (empty: left out)
  std::string output_dir;         // real-recordings.md, real-consistency.md and pictures; empty: stdout only
  std::string image_prefix;       // how real-recordings.md refers to the pictures' directory
  double carmen_range_max = 80.0;
};

int runReportReal(const ReportRealOptions& options);
int runBenchAccuracy(const BenchAccuracyOptions& options);
int runDiff(const DiffOptions& options);
int runMap(const MapOptions& options);
int runSimulate(const SimulateOptions& options);
int runReplay(const ReplayOptions& options);
int runRender(const RenderOptionsCli& options);
int runInfo(const InfoOptions& options);

}  // namespace scanfilter::cli
