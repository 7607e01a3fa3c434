// The accuracy table of docs/accuracy.md: every built-in scene, held-out
// seeds, the shipped defaults beside the paper-literal reading and step 1
// alone; one table per sensor asked for (default: each scene's own sensor),
// then the recall per artefact cause over every scene.
//   build/bench/accuracy_table [--seeds 2,3] [--config-dir config] [--sensor tof,triangulation] [--max-frames N]
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli_checks.hpp"
#include "scanfilter/accuracy/filter_score.hpp"
#include "scanfilter/accuracy/labelled_logs.hpp"
#include "scanfilter/input_error.hpp"

using namespace scanfilter;

namespace {

// Artefacts F1 is the accuracy issue's measure: both kinds as one class
// against the valid points, whatever label a removed artefact got.
void row(const std::string& scene, const std::string& filter, const RemovalScore& s) {
  std::printf(
      "| %s | %s | %.3f / %.3f / **%.3f** | %.3f / %.3f / **%.3f** | %.3f / %.3f / **%.3f** | %.2f %% | %.1f %% "
      "|\n",
      scene.c_str(), filter.c_str(), s.jump().precision(), s.jump().recall(), s.jump().f1(), s.misdetected().precision(),
      s.misdetected().recall(), s.misdetected().f1(), s.artefactPrecision(), s.artefactRecall(), s.artefactF1(),
      100 * s.falseDeletionRate(), 100 * s.thinLegRetention());
}

// Recall per artefact cause (simulator ground truth), every scene together:
// the view external labelled simulators report.
void causeTable(const std::vector<std::pair<std::string, RemovalScore>>& scores) {
  std::printf("\n| filter: recall by cause (artefacts) |");
  for (ArtefactCause cause : kEveryArtefactCause) std::printf(" %s |", artefactCauseName(cause));
  std::printf("\n|---|");
  for (std::size_t c = 0; c < kEveryArtefactCause.size(); ++c) std::printf("---|");
  std::printf("\n");
  for (const auto& [name, score] : scores) {
    std::printf("| %s |", name.c_str());
    for (ArtefactCause cause : kEveryArtefactCause) {
      if (score.causeTruth(cause) == 0)
        std::printf(" - |");  // the sensor makes none
      else
        std::printf(" %.3f (%zu) |", score.causeRecall(cause), score.causeTruth(cause));
    }
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::uint64_t> seeds = {2, 3};
  std::string config_dir = SCANFILTER_SOURCE_DIR "/config";
  std::vector<std::string> sensors;
  int max_frames = 0;
  bool defaults_only = false;
  std::vector<std::string> variants;
  CLI::App app{"The accuracy table of docs/accuracy.md: the shipped defaults, the paper-literal reading and step 1 "
               "alone on every built-in scene"};
  bench::addHeldOutSeedsOption(app, seeds);
  app.add_option("--config-dir", config_dir, "directory with filter.yaml and filter-paper-literal.yaml")
      ->capture_default_str()
      ->check(CLI::ExistingDirectory);
  app.add_option("--sensor", sensors,
                 "sensor presets (config/sensors: tof, triangulation) or preset files, one table each; default: each "
                 "scene's own sensor")
      ->delimiter(',');
  bench::addMaxFramesOption(app, max_frames);
  app.add_flag("--defaults-only", defaults_only,
               "score filter.yaml alone (a third of the time: for comparing a config variant)");
  app.add_option("--variant", variants,
                 "score these filter config files instead, each on the same simulated logs (repeat the option)")
      ->allow_extra_args(false)
      ->check(CLI::ExistingFile);
  CLI11_PARSE(app, argc, argv);
  if (sensors.empty()) sensors.emplace_back();  // the scenes' own

  FilterConfig defaults, literal;
  try {
    defaults = loadFilterConfig(config_dir + "/filter.yaml");
    literal = loadFilterConfig(config_dir + "/filter-paper-literal.yaml");
  } catch (const std::exception& e) {  // a missing or malformed file: say which, not a crash
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  FilterConfig step1_only = defaults;
  step1_only.params.penetration_enabled = false;
  step1_only.params.penetration.rescue_persistent_points = false;
  std::vector<std::pair<std::string, FilterConfig>> filters = {
      {"defaults", defaults}, {"paper literal", literal}, {"step 1 only, no rescue", step1_only}};
  if (defaults_only) filters.resize(1);
  if (!variants.empty()) {
    filters.clear();
    try {
      for (const auto& path : variants) filters.emplace_back(path, loadFilterConfig(path));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 2;
    }
  }

  try {
    for (const auto& sensor : sensors) {
      accuracy::SceneVariant seen_by;
      seen_by.sensor = sensor;
      if (sensors.size() > 1 || !sensor.empty())
        std::printf("%s**sensor: %s**\n\n", &sensor == &sensors.front() ? "" : "\n", sensor.c_str());
      std::printf(
          "| scene | filter | jump P / R / F1 | misdetected P / R / F1 | artefacts P / R / F1 | valid deleted "
          "| thin legs kept |\n");
      std::printf("|---|---|---|---|---|---|---|\n");
      std::vector<accuracy::LabelledLog> all;
      for (const auto& scene : sim::builtinSceneNames()) {
        std::vector<accuracy::LabelledLog> logs;
        for (auto seed : seeds) logs.push_back(accuracy::simulateScene(scene, seed, max_frames, seen_by));
        for (const auto& [name, config] : filters) row(scene, name, accuracy::scoreFilter(config, logs).score);
        all.insert(all.end(), logs.begin(), logs.end());
      }
      std::vector<std::pair<std::string, RemovalScore>> scores;
      for (const auto& [name, config] : filters) {
        scores.emplace_back(name, accuracy::scoreFilter(config, all).score);
        row("**all**", name, scores.back().second);
      }
      causeTable(scores);
    }
  } catch (const InputError& e) {  // an unknown sensor: say which
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}
