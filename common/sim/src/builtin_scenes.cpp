#include <filesystem>

#include "builtin_texts.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

std::vector<std::string> builtinSceneNames() { return builtinNames(builtinSceneTexts()); }

Scene findScene(const std::string& name_or_path) {
  if (const auto text = builtinText(builtinSceneTexts(), name_or_path))
    return parseScene(*text, "builtin scene " + name_or_path);
  std::error_code error;  // a name too long is "no such file", not an exception
  if (std::filesystem::exists(name_or_path, error)) return loadScene(name_or_path);
  throw InputError(name_or_path, 0, "",
                   "no such scene file, and not a built-in scene (" + namesList(builtinSceneTexts()) + ")");
}

}  // namespace scanfilter::sim
