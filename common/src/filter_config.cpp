#include "scanfilter/filter_config.hpp"

#include <fstream>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "scanfilter/input_error.hpp"

namespace scanfilter {

namespace {

// Reads one YAML mapping, remembering which keys were used so the rest can be
// reported as unknown.
class Section {
 public:
  Section(const YAML::Node& root, const std::string& key, const std::string& file)
      : file_(file), path_(key), node_(root[key]) {  // init, not assign: yaml-cpp's = writes through
    if (node_ && !node_.IsMap()) fail(path_, node_, "expected a mapping");
  }

  bool present() const { return static_cast<bool>(node_); }

  template <typename T>
  void read(const char* key, T& value) {
    const YAML::Node v = take(key);
    if (!v) return;
    try {
      value = v.as<T>();
    } catch (const YAML::Exception&) {
      fail(path_ + "." + key, v, "expected " + typeName<T>() + ", got \"" + scalar(v) + "\"");
    }
  }

  // A number or the word `auto`.
  void readAuto(const char* key, std::optional<double>& value) {
    const YAML::Node v = take(key);
    if (!v) return;
    if (v.IsScalar() && v.Scalar() == "auto") {
      value.reset();
      return;
    }
    double x = 0.0;
    try {
      x = v.as<double>();
    } catch (const YAML::Exception&) {
      fail(path_ + "." + key, v, "expected a number or auto, got \"" + scalar(v) + "\"");
    }
    value = x;
  }

  void readSpanRange(const char* key, SpanRange& value) {
    const YAML::Node v = take(key);
    if (!v) return;
    if (v.IsScalar() && v.Scalar() == "cluster_mean") value = SpanRange::kClusterMean;
    else if (v.IsScalar() && v.Scalar() == "seed") value = SpanRange::kSeed;
    else fail(path_ + "." + key, v, "expected cluster_mean or seed, got \"" + scalar(v) + "\"");
  }

  void requireRange(const char* key, double value, double lo, double hi, const char* expected) {
    if (!(value >= lo && value <= hi)) fail(path_ + "." + key, node_[key], std::string("expected ") + expected);
  }

  [[noreturn]] void failKey(const char* key, const std::string& problem) const {
    fail(path_ + "." + key, node_[key], problem);
  }

  void rejectUnknownKeys() {
    if (!node_) return;
    for (const auto& entry : node_) {
      const auto key = entry.first.as<std::string>();
      if (!used_.count(key)) fail(path_ + "." + key, entry.first, "unknown key");
    }
  }

  [[noreturn]] void fail(const std::string& key, const YAML::Node& at, const std::string& problem) const {
    const std::size_t line = at && at.Mark().line >= 0 ? static_cast<std::size_t>(at.Mark().line) + 1 : 0;
    throw InputError(file_, line, key, problem);
  }

 private:
  YAML::Node take(const char* key) {
    used_.insert(key);
    return node_ ? node_[key] : YAML::Node(YAML::NodeType::Undefined);
  }
  static std::string scalar(const YAML::Node& v) { return v.IsScalar() ? v.Scalar() : "a non-scalar"; }
  template <typename T>
  static std::string typeName() {
    if constexpr (std::is_same_v<T, bool>) return "true or false";
    else if constexpr (std::is_integral_v<T>) return "an integer";
    else return "a number";
  }

  std::string file_;
  std::string path_;
  YAML::Node node_;
  std::set<std::string> used_;
};

void readJump(Section& s, FilterConfig& config) {
  JumpFilterParams& p = config.params.jump;
  s.read("enabled", config.params.jump_enabled);
  s.readAuto("angular_accuracy_deg", config.angular_accuracy_deg);
  s.read("alpha", p.alpha);
  s.read("theta_k_deg", p.theta_k_deg);
  s.read("l_min", p.l_min);
  s.read("l_max", p.l_max);
  s.readAuto("d_min", config.d_min);
  s.readAuto("d_max", config.d_max);
  s.readSpanRange("span_range", p.span_range);
  if (config.angular_accuracy_deg) s.requireRange("angular_accuracy_deg", *config.angular_accuracy_deg, 1e-6, 90.0, "0 < value <= 90");
  s.requireRange("alpha", p.alpha, 1e-9, 1e9, "a value > 0");
  s.requireRange("theta_k_deg", p.theta_k_deg, 0.0, 89.9, "0 <= value < 90 (cos θK must stay positive)");
  s.requireRange("l_min", p.l_min, 0.0, 1e9, "a value >= 0");
  s.requireRange("l_max", p.l_max, 0.0, 1e9, "a value >= 0");
  if (config.d_min && config.d_max && !(*config.d_max > *config.d_min)) s.failKey("d_max", "expected d_max > d_min");
  s.rejectUnknownKeys();
}

void readPenetration(Section& s, FilterConfig& config) {
  PenetrationFilterParams& p = config.params.penetration;
  s.read("enabled", config.params.penetration_enabled);
  s.read("cell_size", p.cell_size);
  s.read("frame_lifetime", p.frame_lifetime);
  s.read("min_frames", p.min_frames);
  s.read("obstacle_threshold", p.obstacle_threshold);
  s.read("corridor_half_width", p.corridor_half_width);
  s.read("obstacle_at_centroid", p.obstacle_at_centroid);
  s.read("require_both_sides", p.require_both_sides);
  s.read("straddle_half_width", p.straddle_half_width);
  s.read("surface_gap", p.surface_gap);
  s.read("own_surface_margin", p.own_surface_margin);
  s.read("own_surface_margin_per_m", p.own_surface_margin_per_m);
  s.read("behind_margin", p.behind_margin);
  s.read("pose_jump_reset", p.pose_jump_reset);
  s.read("max_cache_frames", p.max_cache_frames);
  s.read("cache_misdetected_points", p.cache_misdetected_points);
  s.read("rescue_persistent_points", p.rescue_persistent_points);
  s.read("rescue_min_count", p.rescue_min_count);
  s.read("rescue_radius", p.rescue_radius);
  s.requireRange("cell_size", p.cell_size, 1e-3, 10.0, "0.001 <= value <= 10 (m)");
  s.requireRange("frame_lifetime", p.frame_lifetime, 0.0, 1e9, "a value >= 0 (s)");
  s.requireRange("min_frames", p.min_frames, 1, 1e9, "an integer >= 1");
  s.requireRange("obstacle_threshold", p.obstacle_threshold, 0, 1e9, "an integer >= 0");
  s.requireRange("corridor_half_width", p.corridor_half_width, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("own_surface_margin", p.own_surface_margin, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("own_surface_margin_per_m", p.own_surface_margin_per_m, 0.0, 1e9, "a value >= 0");
  s.requireRange("straddle_half_width", p.straddle_half_width, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("surface_gap", p.surface_gap, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("behind_margin", p.behind_margin, 0.0, 1e9, "a value >= 0 (m)");
  s.requireRange("pose_jump_reset", p.pose_jump_reset, 0.0, 1e9, "a value > 0 (m)");
  s.requireRange("max_cache_frames", static_cast<double>(p.max_cache_frames), 1, 1e7, "an integer >= 1");
  s.requireRange("rescue_min_count", p.rescue_min_count, 1, 1e9, "an integer >= 1");
  s.requireRange("rescue_radius", p.rescue_radius, 0.0, 1.0, "0 <= value <= 1 (m)");
  s.rejectUnknownKeys();
}

}  // namespace

FilterConfig parseFilterConfig(const std::string& yaml_text, const std::string& name) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    throw InputError(name, static_cast<std::size_t>(e.mark.line) + 1, "", "malformed YAML: " + e.msg);
  }
  FilterConfig config;
  if (!root || root.IsNull()) return config;
  if (!root.IsMap()) throw InputError(name, 1, "", "expected a mapping at the top level");
  const std::set<std::string> sections = {"jump_filter", "penetration_filter"};
  for (const auto& entry : root) {
    const auto key = entry.first.as<std::string>();
    if (!sections.count(key))
      throw InputError(name, static_cast<std::size_t>(entry.first.Mark().line) + 1, key,
                       "unknown section; expected jump_filter or penetration_filter");
  }
  Section jump(root, "jump_filter", name);
  readJump(jump, config);
  Section penetration(root, "penetration_filter", name);
  readPenetration(penetration, config);
  return config;
}

FilterConfig loadFilterConfig(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot open config file");
  std::stringstream text;
  text << in.rdbuf();
  return parseFilterConfig(text.str(), path);
}

TwoStepFilterParams FilterConfig::resolve(const SensorInfo& sensor) const {
  TwoStepFilterParams out = params;
  out.jump.angular_accuracy_deg = angular_accuracy_deg.value_or(sensor.angular_accuracy_deg);
  out.jump.d_min = d_min.value_or(sensor.range_min);
  out.jump.d_max = d_max.value_or(sensor.range_max);
  return out;
}

}  // namespace scanfilter
