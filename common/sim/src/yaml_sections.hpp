#pragma once
// Reading a scene's or a sensor preset's YAML: typed values with errors that
// name the file, line and key, and the sections both kinds of file share.
// Internal to scanfilter_sim.
#include <cmath>
#include <set>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scanfilter/input_error.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

// Reads typed values out of YAML with errors that name file, line and key.
class SceneParser {
 public:
  explicit SceneParser(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& key, const std::string& problem) const {
    const std::size_t line = at && at.Mark().line >= 0 ? static_cast<std::size_t>(at.Mark().line) + 1 : 0;
    throw InputError(file_, line, key, problem);
  }

  void checkKeys(const YAML::Node& map, const std::string& path, const std::set<std::string>& allowed) const {
    if (!map.IsMap()) fail(map, path, "expected a mapping");
    for (const auto& entry : map) {
      if (!entry.first.IsScalar()) fail(entry.first, path, "expected plain keys, got a non-scalar key");
      const std::string& key = entry.first.Scalar();
      if (!allowed.count(key)) fail(entry.first, path + "." + key, "unknown key");
    }
  }

  double number(const YAML::Node& map, const std::string& path, const char* key, double fallback) const {
    const YAML::Node v = map[key];
    if (!v) return fallback;
    try {
      const double x = v.as<double>();
      if (std::isfinite(x)) return x;
    } catch (const YAML::Exception&) {
    }
    fail(v, path + "." + key, "expected a finite number");
  }

  double positive(const YAML::Node& map, const std::string& path, const char* key, double fallback) const {
    const double x = number(map, path, key, fallback);
    if (!(x > 0.0)) fail(map[key], path + "." + key, "expected a value > 0");
    return x;
  }

  double probability(const YAML::Node& map, const std::string& path, const char* key, double fallback) const {
    const double x = number(map, path, key, fallback);
    if (!(x >= 0.0 && x <= 1.0)) fail(map[key], path + "." + key, "expected a probability in [0, 1]");
    return x;
  }

  Eigen::Vector2d point(const YAML::Node& v, const std::string& path) const {
    if (!v || !v.IsSequence() || v.size() != 2) fail(v, path, "expected [x, y]");
    try {
      return {v[0].as<double>(), v[1].as<double>()};
    } catch (const YAML::Exception&) {
      fail(v, path, "expected [x, y] with numbers");
    }
  }

  // A scalar's text (a word, a name); a list or a mapping is an error.
  std::string text(const YAML::Node& v, const std::string& path) const {
    if (!v.IsScalar()) fail(v, path, "expected a string, got a list or mapping");
    return v.Scalar();
  }

  bool boolean(const YAML::Node& v, const std::string& path) const {
    try {
      return v.as<bool>();
    } catch (const YAML::Exception&) {
      fail(v, path, "expected true or false");
    }
  }

  // A three-number pose [x, y, yaw].
  SensorMount mount(const YAML::Node& v, const std::string& path) const {
    if (!v.IsSequence() || v.size() != 3) fail(v, path, "expected [x, y, yaw]");
    try {
      return {v[0].as<double>(), v[1].as<double>(), v[2].as<double>()};
    } catch (const YAML::Exception&) {
      fail(v, path, "expected [x, y, yaw] with numbers");
    }
  }

  Material material(const YAML::Node& map, const std::string& path) const {
    const YAML::Node v = map["material"];
    if (!v) return Material::kRough;
    const std::string m = text(v, path + ".material");
    if (m == "rough") return Material::kRough;
    if (m == "smooth") return Material::kSmooth;
    if (m == "glass") return Material::kGlass;
    fail(v, path + ".material", "expected rough, smooth or glass, got \"" + m + "\"");
  }

  // A whole number from 1 to `max` (a bound keeps the conversion to int
  // defined and the arrays sized by it within memory).
  int count(const YAML::Node& map, const std::string& path, const char* key, int fallback, int max) const {
    const double x = number(map, path, key, fallback);
    if (!(x >= 1.0 && x <= max) || x != std::floor(x))
      fail(map[key], path + "." + key, "expected a whole number from 1 to " + std::to_string(max));
    return static_cast<int>(x);
  }

  const YAML::Node sequence(const YAML::Node& root, const char* key) const {
    const YAML::Node v = root[key];
    if (v && !v.IsSequence()) fail(v, key, "expected a list");
    return v;
  }

 private:
  std::string file_;
};

// The `sensor` section (with_mount: the robot's mount and beam direction
// too; a sensor preset leaves those to the scene), the `lidar` section and the
// `odometry` section. Each key left out keeps its value.
void readSensor(const SceneParser& p, const YAML::Node& node, Scene& scene, bool with_mount);
void readLidar(const SceneParser& p, const YAML::Node& node, LidarModel& m);
void readOdometry(const SceneParser& p, const YAML::Node& node, OdometryDrift& drift);

}  // namespace scanfilter::sim
