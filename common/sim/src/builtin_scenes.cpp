#include <filesystem>
#include <string_view>
#include <utility>
#include <vector>

#include "scanfilter/input_error.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

// Defined in the generated builtin_scenes_embedded.cpp (see common/sim/embed_scenes.cmake).
const std::vector<std::pair<std::string_view, std::string_view>>& builtinSceneTexts();

std::vector<std::string> builtinSceneNames() {
  std::vector<std::string> names;
  for (const auto& [name, text] : builtinSceneTexts()) names.emplace_back(name);
  return names;
}

Scene findScene(const std::string& name_or_path) {
  for (const auto& [name, text] : builtinSceneTexts())
    if (name == name_or_path) return parseScene(std::string(text), "builtin scene " + name_or_path);
  if (std::filesystem::exists(name_or_path)) return loadScene(name_or_path);
  std::string known;
  for (const auto& name : builtinSceneNames()) known += (known.empty() ? "" : ", ") + name;
  throw InputError(name_or_path, 0, "", "no such scene file, and not a built-in scene (" + known + ")");
}

}  // namespace scanfilter::sim
