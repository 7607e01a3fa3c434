#pragma once
// Looking up the YAML files compiled into the binary (embed_yaml.cmake).
// Internal to scanfilter_sim.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace scanfilter::sim {

using BuiltinTexts = std::vector<std::pair<std::string_view, std::string_view>>;

// Defined in the generated builtin_*_embedded.cpp.
const BuiltinTexts& builtinSceneTexts();
const BuiltinTexts& builtinSensorTexts();

inline std::vector<std::string> builtinNames(const BuiltinTexts& texts) {
  std::vector<std::string> names;
  for (const auto& [name, text] : texts) names.emplace_back(name);
  return names;
}

inline std::optional<std::string> builtinText(const BuiltinTexts& texts, const std::string& name) {
  for (const auto& [n, text] : texts)
    if (n == name) return std::string(text);
  return std::nullopt;
}

// "a, b, c": the names an error message offers.
inline std::string namesList(const BuiltinTexts& texts) {
  std::string known;
  for (const auto& name : builtinNames(texts)) known += (known.empty() ? "" : ", ") + name;
  return known;
}

}  // namespace scanfilter::sim
