#pragma once
#include <charconv>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <type_traits>

#include <yaml-cpp/yaml.h>

#include "scanfilter/input_error.hpp"

namespace scanfilter {

// Reads one YAML mapping of a config file with errors that name the file, the
// line and the key, and remembers which keys were read so that the others can
// be reported as unknown (a misspelt key would otherwise be ignored).
class YamlSection {
 public:
  // The mapping under `key` in `parent` (absent: every read keeps its default).
  YamlSection(const YAML::Node& parent, const std::string& key, std::string file, std::string path_prefix = "");

  bool present() const { return static_cast<bool>(node_); }
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  const YAML::Node& node() const { return node_; }

  template <typename T>
  void read(const char* key, T& value) {
    const YAML::Node v = take(key);
    if (!v) return;
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
      if (!readDecimal(v, value))
        fail(key, "expected " + typeName<T>() + outOfTypeRange<T>(v) + ", got \"" + scalar(v) + "\"");
    } else {
      try {
        value = v.as<T>();
      } catch (const YAML::Exception&) {
        fail(key, "expected " + typeName<T>() + ", got \"" + scalar(v) + "\"");
      }
    }
  }

  // A number or the word `auto` (unset).
  void readAuto(const char* key, std::optional<double>& value);

  // One of `choices`.
  void readChoice(const char* key, std::string& value, const std::set<std::string>& choices);

  // Marks a key as known without reading it (a subsection read elsewhere).
  YAML::Node take(const char* key);

  // Fails naming `expected` and the value as the file gave it (or, for a
  // default a setting elsewhere made invalid, as it stands).
  void requireRange(const char* key, double value, double lo, double hi, const char* expected) const {
    if (!(value >= lo && value <= hi)) failOutOfRange(key, value, expected);
  }

  // Fails unless `path` (the key's value, resolved) names an existing file,
  // or folder, so that a wrong path is reported at the line that gave it;
  // `note` is added to the message (what the folder is for).
  void requireFile(const char* key, const std::string& path) const;
  void requireFolder(const char* key, const std::string& path, const std::string& note) const;

  // A key that no read asked for is an error; a known key within a few
  // letters of it is named (a misspelling), else the known keys are listed.
  void rejectUnknownKeys() const;

  [[noreturn]] void fail(const char* key, const std::string& problem) const;

 private:
  [[noreturn]] void failOutOfRange(const char* key, double value, const char* expected) const;
  std::string unknownKeyProblem(const std::string& key) const;
  static std::string scalar(const YAML::Node& v) { return v.IsScalar() ? v.Scalar() : "a list or mapping"; }
  // An integer in decimal, as a person writes it: yaml-cpp would read 010
  // as octal 8 and 0x10 as 16.
  template <typename T>
  static bool readDecimal(const YAML::Node& v, T& value) {
    if (!v.IsScalar()) return false;
    const std::string& text = v.Scalar();
    const char* first = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
    const char* last = text.data() + text.size();
    T parsed{};
    const auto [end, error] = std::from_chars(first, last, parsed, 10);
    if (error != std::errc() || end != last || first == last) return false;
    value = parsed;
    return true;
  }
  // An integer the type cannot hold (-1 for a count, 1e20 digits) is one all
  // the same: the message says which integers are.
  template <typename T>
  static std::string outOfTypeRange(const YAML::Node& v) {
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>) {
      const std::string text = v.IsScalar() ? v.Scalar() : "";
      const std::size_t digits = !text.empty() && (text[0] == '-' || text[0] == '+') ? 1 : 0;
      if (text.size() > digits && text.find_first_not_of("0123456789", digits) == std::string::npos)
        return " from " + std::to_string(std::numeric_limits<T>::min()) + " to " +
               std::to_string(std::numeric_limits<T>::max());
    }
    return "";
  }
  template <typename T>
  static std::string typeName() {
    if constexpr (std::is_same_v<T, bool>) return "true or false";
    else if constexpr (std::is_same_v<T, std::string>) return "a string";
    else if constexpr (std::is_integral_v<T>) return "an integer";
    else return "a number";
  }

  std::string file_;
  std::string path_;
  YAML::Node node_;
  std::set<std::string> used_;
};

// The text of a mapping's key; a list or mapping used as a key is an error
// naming the file and line (yaml-cpp would throw its own exception).
std::string keyText(const YAML::Node& key, const std::string& file);

// Parses YAML text, reporting syntax errors and a key given twice in one
// mapping with file and line.
YAML::Node parseYaml(const std::string& text, const std::string& file);
// Largest config file read (scenes with many walls are ~10 kB): a bigger one
// is not a config, and reading it whole (a 2 GB line) would take the memory.
inline constexpr std::size_t kMaxConfigBytes = std::size_t{16} << 20;
// A config file's text; InputError for a missing file, a directory or a file
// over kMaxConfigBytes.
std::string readConfigText(const std::string& path);
// Reads and parses a YAML file.
YAML::Node loadYamlFile(const std::string& path);

}  // namespace scanfilter
