#include "scanfilter/yaml_section.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace scanfilter {

namespace {
std::size_t lineOf(const YAML::Node& node) {
  return node && node.Mark().line >= 0 ? static_cast<std::size_t>(node.Mark().line) + 1 : 0;
}
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
    if (!used_.count(key)) throw InputError(file_, lineOf(entry.first), path_ + "." + key, "unknown key");
  }
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
  try {
    return YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw InputError(file, static_cast<std::size_t>(e.mark.line) + 1, "", "malformed YAML: " + e.msg);
  }
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
