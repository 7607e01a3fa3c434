#include "scanfilter/yaml_section.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace scanfilter {

namespace {
std::size_t lineOf(const YAML::Node& node) {
  return node && node.Mark().line >= 0 ? static_cast<std::size_t>(node.Mark().line) + 1 : 0;
}

// A misspelt key is this many letters (inserted, dropped, changed or two
// swapped) from the key meant: `alpah`, `queue_dept`, `min_cels`.
constexpr std::size_t kMaxMisspelling = 2;
// An unknown key in a section with more keys than this names none of them:
// the documented config file lists them better than one long line.
constexpr std::size_t kMaxKeysListed = 12;

// Letters inserted, dropped, changed or two neighbours swapped to turn `a`
// into `b` (optimal string alignment distance).
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t change = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + change});
      const bool swapped = i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1];
      if (swapped) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  }
  return d[a.size()][b.size()];
}

std::string childPath(const std::string& path, const std::string& child) {
  return path.empty() ? child : path + "." + child;
}

// What keeps `path` from being used as a file (or a folder), or nothing.
// The error_code forms: a name too long for the file system is not a
// filesystem_error thrown (found by penetration_filter_config_fuzz); and
// a path that could not be looked at (a folder the service's user may not
// enter) is said as such, not as "no such file".
std::optional<std::string> pathProblem(const std::string& path, bool folder) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (error && error != std::errc::no_such_file_or_directory)
    return "cannot look at " + path + ": " + error.message();
  if (!std::filesystem::exists(status)) return (folder ? "no such folder: " : "no such file: ") + path;
  if (folder && !std::filesystem::is_directory(status)) return "not a folder: " + path;
  if (!folder && std::filesystem::is_directory(status)) return "is a directory, expected a file: " + path;
  return std::nullopt;
}

// YAML allows a key once in a mapping. yaml-cpp keeps both entries and
// answers the first, so a line appended to override a setting would be
// ignored without a word. Each mapping is checked once, where it is written:
// an alias (*x) is the node its anchor (&x) names, so following aliases
// would walk a cycle for ever, or a chain of them a billion times.
class DuplicateKeyCheck {
 public:
  explicit DuplicateKeyCheck(const std::string& file) : file_(file) {}

  void check(const YAML::Node& node, const std::string& path) {
    if (!node.IsSequence() && !node.IsMap()) return;
    if (!checked_.insert(node.Mark().pos).second) return;  // an alias of a node checked already
    if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) check(node[i], path + "[" + std::to_string(i) + "]");
      return;
    }
    std::map<std::string, std::size_t> first_line;
    for (const auto& entry : node) {
      if (!entry.first.IsScalar()) continue;  // keyText reports it where the key is read
      const std::string& key = entry.first.Scalar();
      const auto [seen, fresh] = first_line.emplace(key, lineOf(entry.first));
      if (!fresh)
        throw InputError(file_, lineOf(entry.first), childPath(path, key),
                         "duplicate key (first on line " + std::to_string(seen->second) + "); give each key once");
      check(entry.second, childPath(path, key));
    }
  }

 private:
  const std::string& file_;
  std::set<int> checked_;  // the text positions of the mappings and lists checked
};
}  // namespace

YamlSection::YamlSection(const YAML::Node& parent, const std::string& key, std::string file, std::string path_prefix)
    : file_(std::move(file)),
      path_(path_prefix.empty() ? key : path_prefix + "." + key),
      // init, not assign: yaml-cpp's operator= writes through. An absent
      // parent (a subsection of a missing section) has no children.
      node_(parent ? parent[key] : YAML::Node(YAML::NodeType::Undefined)) {
  if (node_ && !node_.IsMap()) throw InputError(file_, lineOf(node_), path_, "expected a mapping");
}

YAML::Node YamlSection::take(const char* key) {
  used_.insert(key);
  return node_ ? node_[key] : YAML::Node(YAML::NodeType::Undefined);
}

void YamlSection::readAuto(const char* key, std::optional<double>& value) {
  const YAML::Node v = take(key);
  if (!v) return;
  if (v.IsScalar() && v.Scalar() == "auto") {
    value.reset();
    return;
  }
  try {
    value = v.as<double>();
  } catch (const YAML::Exception&) {
    fail(key, "expected a number or auto, got \"" + scalar(v) + "\"");
  }
}

void YamlSection::readChoice(const char* key, std::string& value, const std::set<std::string>& choices) {
  const YAML::Node v = take(key);
  if (!v) return;
  const std::string text = v.IsScalar() ? v.Scalar() : "";
  if (choices.count(text)) {
    value = text;
    return;
  }
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  fail(key, "expected one of " + list + ", got \"" + scalar(v) + "\"");
}

void YamlSection::rejectUnknownKeys() const {
  if (!node_) return;
  for (const auto& entry : node_) {
    const std::string key = keyText(entry.first, file_);
    if (!used_.count(key)) throw InputError(file_, lineOf(entry.first), path_ + "." + key, unknownKeyProblem(key));
  }
}

std::string YamlSection::unknownKeyProblem(const std::string& key) const {
  const std::string* nearest = nullptr;
  std::size_t nearest_distance = 0;
  for (const std::string& known : used_) {
    const std::size_t d = editDistance(key, known);
    if (!nearest || d < nearest_distance) {
      nearest = &known;
      nearest_distance = d;
    }
  }
  // A short key is near every other short key: the edits must leave most of it.
  const bool misspelt = nearest && nearest_distance <= kMaxMisspelling && 2 * nearest_distance < key.size();
  if (misspelt) return "unknown key (did you mean " + *nearest + "?)";
  if (used_.empty()) return "unknown key (this section takes none)";
  if (used_.size() > kMaxKeysListed)
    return "unknown key (not one of the " + std::to_string(used_.size()) + " keys " + path_ + " takes)";
  std::string list;
  for (const std::string& known : used_) list += (list.empty() ? "" : ", ") + known;
  return "unknown key (expected one of " + list + ")";
}

void YamlSection::failOutOfRange(const char* key, double value, const char* expected) const {
  const YAML::Node given = node_ ? node_[key] : YAML::Node(YAML::NodeType::Undefined);
  std::ostringstream text;
  if (given && given.IsScalar()) {
    text << given.Scalar();
  } else {
    text << value;
  }
  // `.inf` is "a value > 0" by arithmetic; what it is not is a number a setting can take.
  if (!std::isfinite(value)) text << " (not a finite number)";
  fail(key, std::string("expected ") + expected + ", got " + text.str());
}

void YamlSection::requireFile(const char* key, const std::string& path) const {
  if (const auto problem = pathProblem(path, false)) fail(key, *problem);
}

void YamlSection::requireFolder(const char* key, const std::string& path, const std::string& note) const {
  if (const auto problem = pathProblem(path, true)) fail(key, *problem + note);
}

void YamlSection::fail(const char* key, const std::string& problem) const {
  const YAML::Node at = node_ ? node_[key] : YAML::Node(YAML::NodeType::Undefined);
  throw InputError(file_, at ? lineOf(at) : lineOf(node_), path_ + "." + key, problem);
}

std::string keyText(const YAML::Node& key, const std::string& file) {
  if (!key.IsScalar()) throw InputError(file, lineOf(key), "", "expected a plain key, got a list or mapping");
  return key.Scalar();
}

YAML::Node parseYaml(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(file, static_cast<std::size_t>(e.mark.line) + 1, "", "malformed YAML: " + e.msg);
  }
  DuplicateKeyCheck(file).check(root, "");
  return root;
}

std::string readConfigText(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) throw InputError(path, 0, "", "is a directory, expected a YAML file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "", std::string("cannot open: ") + std::strerror(errno));
  std::string text;
  constexpr std::size_t kChunk = 64 * 1024;
  char chunk[kChunk];
  while (in.read(chunk, kChunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxConfigBytes) {
      const auto line = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
      throw InputError(path, line, "", "file larger than " + std::to_string(kMaxConfigBytes >> 20) + " MiB; not a config file");
    }
  }
  if (in.bad()) throw InputError(path, 0, "", "read error");
  return text;
}

YAML::Node loadYamlFile(const std::string& path) {
  YAML::Node root = parseYaml(readConfigText(path), path);
  // Nothing but blanks and comments: most likely a file cut short or the
  // wrong file, never a config meaning "all defaults".
  if (!root || root.IsNull()) throw InputError(path, 0, "", "empty file: expected a YAML mapping");
  return root;
}

}  // namespace scanfilter
