// The accuracy table of docs/accuracy.md: every built-in scene, held-out
// seeds, the shipped defaults beside the paper-literal reading and step 1
// alone.
//   build/bench/accuracy_table [--seeds 2,3] [--config-dir config]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "labelled_logs.hpp"

using namespace scanfilter;

namespace {

void row(const std::string& scene, const std::string& filter, const RemovalScore& s) {
  std::printf("| %s | %s | %.3f / %.3f / **%.3f** | %.3f / %.3f / **%.3f** | %.2f %% | %.1f %% |\n", scene.c_str(),
              filter.c_str(), s.jump().precision(), s.jump().recall(), s.jump().f1(), s.misdetected().precision(),
              s.misdetected().recall(), s.misdetected().f1(), 100 * s.falseDeletionRate(), 100 * s.thinLegRetention());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::uint64_t> seeds = {2, 3};
  std::string config_dir = SCANFILTER_SOURCE_DIR "/config";
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--config-dir") config_dir = argv[i + 1];
    if (flag == "--seeds") {
      seeds.clear();
      for (char* p = argv[i + 1]; *p;) {
        seeds.push_back(std::strtoull(p, &p, 10));
        if (*p == ',') ++p;
      }
    }
  }
  const FilterConfig defaults = loadFilterConfig(config_dir + "/filter.yaml");
  const FilterConfig literal = loadFilterConfig(config_dir + "/filter-paper-literal.yaml");
  FilterConfig step1_only = defaults;
  step1_only.params.penetration_enabled = false;
  step1_only.params.penetration.rescue_persistent_points = false;
  const std::vector<std::pair<std::string, FilterConfig>> filters = {
      {"defaults", defaults}, {"paper literal", literal}, {"step 1 only, no rescue", step1_only}};

  std::printf("| scene | filter | jump P / R / F1 | misdetected P / R / F1 | valid deleted | thin legs kept |\n");
  std::printf("|---|---|---|---|---|---|\n");
  std::vector<bench::LabelledLog> all;
  for (const auto& scene : sim::builtinSceneNames()) {
    std::vector<bench::LabelledLog> logs;
    for (auto seed : seeds) logs.push_back(bench::simulateScene(scene, seed));
    for (const auto& [name, config] : filters) row(scene, name, bench::scoreFilter(logs, config));
    all.insert(all.end(), logs.begin(), logs.end());
  }
  for (const auto& [name, config] : filters) row("**all**", name, bench::scoreFilter(all, config));
  return 0;
}
