// scanfilter: the command-line tool. CLI11 lives in this file only (it is
// slow to compile); each subcommand's work is in its own *_command.cpp.
#include <exception>
#include <iostream>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "commands.hpp"
#include "scanfilter/cli/option_checks.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/plausible_bounds.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/sim/lidar_model.hpp"

using namespace scanfilter::cli;

namespace {
// Every command that reads a CARMEN log takes its "no return" reading.
void addCarmenRangeMax(CLI::App* command, double& range_max) {
  command->add_option("--carmen-range-max", range_max, "CARMEN logs: ranges at or above this are no return (m)")
      ->check(numberFromTo(scanfilter::kMinCarmenRangeMax, scanfilter::kMaxPlausibleRange, "m"))
      ->capture_default_str();
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"scanfilter: two-step filter for indoor 2D LiDAR scans (jump points, misdetected points)"};
  // Bad arguments: one line (what and which), no usage dump.
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string(e.what()) + " (see --help)\n"; });
  app.set_version_flag("--version", std::string("scanfilter ") + SCANFILTER_VERSION);
  app.require_subcommand(1);
  std::string log_level = "warn";
  app.add_option("--log-level", log_level, "trace, debug, info, warn, error or off")
      ->capture_default_str()
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));

  SimulateOptions sim;
  auto* simulate = app.add_subcommand("simulate", "Simulate a labelled scan log of a scene");
  simulate->add_option("--scene", sim.scene, "built-in scene name (hall, home, office) or a scene YAML file")->capture_default_str();
  simulate->add_option("--sensor", sim.sensor, "sensor preset (tof, triangulation) or a sensor YAML file; default: the scene's own sensor");
  simulate->add_option("--beams", sim.beams, "beams a turn (angular step 360°/N); default: the sensor's own")
      ->check(CLI::Range(1, scanfilter::sim::kMaxSimulatedBeams));
  simulate->add_flag("--true-poses", sim.true_poses, "log the true poses (default: odometry with the scene's drift, 1 %, 0.5°/m)");
  simulate->add_option("--seed", sim.seed, "random seed: same scene and seed, same scans")
      ->capture_default_str()
      ->check(wholeNumber("a seed"));
  simulate->add_option("--max-frames", sim.max_frames, "stop after this many scans (0: whole trajectory)")
      ->check(wholeNumber("a scan count"));
  simulate->add_option("-o,--output", sim.output, "output scan log (.scanlog.jsonl)")->required();

  ReplayOptions replay;
  auto* rep = app.add_subcommand("replay", "Run the two-step filter over a scan log, CARMEN log or Mines URG-04LX log");
  rep->add_option("input", replay.input,
                  "scan log (.scanlog.jsonl), CARMEN log (.log, .gz) or Mines URG-04LX log (.dat)")
      ->required()
      ->check(CLI::ExistingFile);
  rep->add_option("-o,--output", replay.output, "write the input with `labels` added");
  rep->add_option("--config", replay.config, "filter config YAML (default: built-in defaults, see config/filter.yaml)")->check(CLI::ExistingFile);
  rep->add_flag("--reference", replay.reference, "use the literal reference implementations (slow)");
  rep->add_option("--render", replay.render, "also write a before/after PNG of the whole log");
  addCarmenRangeMax(rep, replay.carmen_range_max);
  rep->add_flag("-q,--quiet", replay.quiet, "print nothing but errors");

  RenderOptionsCli render;
  auto* ren = app.add_subcommand("render", "Draw a scan log as PNG: before/after, coloured by truth and labels");
  ren->add_option("input", render.input, "scan log, with or without labels")->required()->check(CLI::ExistingFile);
  ren->add_option("-o,--output", render.output, "PNG file")->required();
  ren->add_option("--title", render.title, "title printed above the panels");
  ren->add_option("--pixels", render.pixels, "size of each panel's longer side")->capture_default_str()->check(CLI::Range(100, 8000));
  ren->add_option("--first-frame", render.first_frame, "first scan drawn (0-based)")->check(wholeNumber("a scan index"));
  ren->add_option("--frames", render.frames, "scans drawn (0: all from the first)")->check(wholeNumber("a scan count"));

  InfoOptions info;
  auto* inf = app.add_subcommand("info", "Summarise a scan log, CARMEN log or Mines URG-04LX log");
  inf->add_option("input", info.input, "scan log, CARMEN log or Mines URG-04LX log")
      ->required()
      ->check(CLI::ExistingFile);
  addCarmenRangeMax(inf, info.carmen_range_max);

  DiffOptions diff;
  auto* dif = app.add_subcommand("diff", "Compare the labels of two scan logs scan by scan (exit 1 if they differ)");
  dif->add_option("first", diff.first, "scan log with labels")->required()->check(CLI::ExistingFile);
  dif->add_option("second", diff.second, "scan log with labels")->required()->check(CLI::ExistingFile);

  MapOptions map;
  auto* mp = app.add_subcommand("map", "Build an occupancy map (ROS map_server PGM + YAML, PNG) from a log");
  mp->add_option("input", map.input, "scan log, CARMEN log or Mines URG-04LX log")
      ->required()
      ->check(CLI::ExistingFile);
  mp->add_option("-o,--output", map.output, "base path of the map files")->required();
  mp->add_option("--config", map.config, "filter config YAML")->check(CLI::ExistingFile);
  mp->add_option("--resolution", map.resolution, "cell size (m)")->capture_default_str()->check(CLI::Range(0.005, 10.0));
  mp->add_flag("--unfiltered", map.unfiltered, "map every return, without the filter (for comparison)");
  addCarmenRangeMax(mp, map.carmen_range_max);

  BenchAccuracyOptions bench;
  auto* ben = app.add_subcommand("bench-accuracy",
                                 "Compare the two-step filter with the baselines on labelled logs (equal tuning budgets)");
  ben->add_option("logs", bench.logs, "labelled scan logs to score on (default: built-in scenes at --seeds)")->check(CLI::ExistingFile);
  ben->add_option("--tune-log", bench.tune_logs, "labelled scan log to tune on (repeatable; default: built-in scenes at --tune-seed)")->check(CLI::ExistingFile);
  ben->add_option("--tune-seed", bench.tune_seed, "simulator seed of the tuning logs")
      ->capture_default_str()
      ->check(wholeNumber("a seed"));
  ben->add_option("--seeds", bench.test_seeds, "simulator seeds of the test logs")
      ->delimiter(',')
      ->capture_default_str()
      ->check(wholeNumber("a seed"));
  ben->add_option("--budget", bench.budget, "sweep evaluations per filter")->capture_default_str()->check(CLI::Range(1, 10000));
  ben->add_option("--config", bench.config, "our filter's config YAML (default: built-in defaults)")->check(CLI::ExistingFile);
  ben->add_option("-o,--output-dir", bench.output_dir, "write accuracy-comparison.md and the PNG figures here");
  ben->add_option("--sensor", bench.sensor, "sensor preset of the simulated logs (tof, triangulation, or a file; default: each scene's own)");
  ben->add_option("--max-frames", bench.max_frames, "scans per simulated log (0: whole trajectory)")
      ->check(wholeNumber("a scan count"));
  // A plain flag and a callback: CLI11 prints a negated flag's default as "{false}".
  ben->add_flag_callback("--no-robustness", [&bench] { bench.robustness = false; },
                         "skip the robustness variants (noise, resolution, drift)");

  ReportRealOptions real;
  auto* rr = app.add_subcommand("report-real",
                                "Real recordings: points removed by reason, maps filtered vs unfiltered, pose-error effects, multi-view consistency");
  rr->add_option("logs", real.logs, "CARMEN, Mines URG-04LX (.dat) or scan logs")->required()->check(CLI::ExistingFile);
  rr->add_option("--config", real.config, "filter config YAML (default: built-in defaults)")->check(CLI::ExistingFile);
  rr->add_option("--literal-config", real.literal_config,
                 "paper-literal filter config (config/filter-paper-literal.yaml), scored beside the others")
      ->check(CLI::ExistingFile);
  rr->add_option("-o,--output-dir", real.output_dir, "write real-recordings.md, real-consistency.md and the pictures here");
  rr->add_option("--image-prefix", real.image_prefix, "path prefix of the pictures in real-recordings.md (e.g. images/)");
  addCarmenRangeMax(rr, real.carmen_range_max);

  CLI11_PARSE(app, argc, argv);
  spdlog::set_level(spdlog::level::from_str(log_level));
  try {
    if (*simulate) return runSimulate(sim);
    if (*rep) return runReplay(replay);
    if (*ren) return runRender(render);
    if (*inf) return runInfo(info);
    if (*dif) return runDiff(diff);
    if (*mp) return runMap(map);
    if (*ben) return runBenchAccuracy(bench);
    if (*rr) return runReportReal(real);
  } catch (const scanfilter::InputError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
