#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "scanfilter/input_error.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

namespace {

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
      const auto key = entry.first.as<std::string>();
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

  Material material(const YAML::Node& map, const std::string& path) const {
    const YAML::Node v = map["material"];
    if (!v) return Material::kRough;
    const std::string m = v.as<std::string>();
    if (m == "rough") return Material::kRough;
    if (m == "smooth") return Material::kSmooth;
    if (m == "glass") return Material::kGlass;
    fail(v, path + ".material", "expected rough, smooth or glass, got \"" + m + "\"");
  }

  const YAML::Node sequence(const YAML::Node& root, const char* key) const {
    const YAML::Node v = root[key];
    if (v && !v.IsSequence()) fail(v, key, "expected a list");
    return v;
  }

 private:
  std::string file_;
};

Eigen::Vector2d rotate(const Eigen::Vector2d& v, double yaw) {
  return {std::cos(yaw) * v.x() - std::sin(yaw) * v.y(), std::sin(yaw) * v.x() + std::cos(yaw) * v.y()};
}

// Corners of a rectangle of `size` centred at `centre`, turned by `yaw`.
std::array<Eigen::Vector2d, 4> rectangle(const Eigen::Vector2d& centre, const Eigen::Vector2d& size, double yaw) {
  const Eigen::Vector2d h = size / 2.0;
  return {centre + rotate({-h.x(), -h.y()}, yaw), centre + rotate({h.x(), -h.y()}, yaw),
          centre + rotate({h.x(), h.y()}, yaw), centre + rotate({-h.x(), h.y()}, yaw)};
}

void readSensor(const SceneParser& p, const YAML::Node& node, Scene& scene) {
  if (!node) return;
  p.checkKeys(node, "sensor", {"mount", "direction", "range_min", "range_max", "angular_accuracy_deg", "beams", "rate_hz"});
  SensorInfo& s = scene.sensor;
  if (const YAML::Node m = node["mount"]) {
    if (!m.IsSequence() || m.size() != 3) p.fail(m, "sensor.mount", "expected [x, y, yaw]");
    s.mount = {m[0].as<double>(), m[1].as<double>(), m[2].as<double>()};
  }
  if (const YAML::Node d = node["direction"]) {
    const auto text = d.as<std::string>();
    if (text != "cw" && text != "ccw") p.fail(d, "sensor.direction", "expected cw or ccw");
    s.direction = text == "cw" ? BeamDirection::kCw : BeamDirection::kCcw;
  }
  s.range_min = p.number(node, "sensor", "range_min", s.range_min);
  s.range_max = p.positive(node, "sensor", "range_max", s.range_max);
  if (!(s.range_max > s.range_min)) p.fail(node["range_max"], "sensor.range_max", "must exceed range_min");
  s.angular_accuracy_deg = p.positive(node, "sensor", "angular_accuracy_deg", s.angular_accuracy_deg);
  scene.lidar.beams = static_cast<int>(p.positive(node, "sensor", "beams", scene.lidar.beams));
  scene.lidar.rate_hz = p.positive(node, "sensor", "rate_hz", scene.lidar.rate_hz);
}

void readLidar(const SceneParser& p, const YAML::Node& node, LidarModel& m) {
  if (!node) return;
  p.checkKeys(node, "lidar",
              {"range_resolution", "noise_sigma_base", "noise_sigma_quadratic", "spot_width_deg", "edge_gap",
               "mixed_probability", "grazing_angle_deg", "grazing_probability", "grazing_error_max",
               "junction_radius", "junction_probability", "junction_error_max", "jump_min_error",
               "smooth_specular_probability", "glass_specular_probability", "glass_transmit_probability",
               "dropout_probability"});
  const std::string s = "lidar";
  m.range_resolution = p.positive(node, s, "range_resolution", m.range_resolution);
  m.noise_sigma_base = p.number(node, s, "noise_sigma_base", m.noise_sigma_base);
  m.noise_sigma_quadratic = p.number(node, s, "noise_sigma_quadratic", m.noise_sigma_quadratic);
  m.spot_width_deg = p.number(node, s, "spot_width_deg", m.spot_width_deg);
  m.edge_gap = p.positive(node, s, "edge_gap", m.edge_gap);
  m.mixed_probability = p.probability(node, s, "mixed_probability", m.mixed_probability);
  m.grazing_angle_deg = p.number(node, s, "grazing_angle_deg", m.grazing_angle_deg);
  m.grazing_probability = p.probability(node, s, "grazing_probability", m.grazing_probability);
  m.grazing_error_max = p.number(node, s, "grazing_error_max", m.grazing_error_max);
  m.junction_radius = p.number(node, s, "junction_radius", m.junction_radius);
  m.junction_probability = p.probability(node, s, "junction_probability", m.junction_probability);
  m.junction_error_max = p.number(node, s, "junction_error_max", m.junction_error_max);
  m.jump_min_error = p.positive(node, s, "jump_min_error", m.jump_min_error);
  m.smooth_specular_probability = p.probability(node, s, "smooth_specular_probability", m.smooth_specular_probability);
  m.glass_specular_probability = p.probability(node, s, "glass_specular_probability", m.glass_specular_probability);
  m.glass_transmit_probability = p.probability(node, s, "glass_transmit_probability", m.glass_transmit_probability);
  m.dropout_probability = p.probability(node, s, "dropout_probability", m.dropout_probability);
}

void readGeometry(const SceneParser& p, const YAML::Node& root, Scene& scene) {
  if (const YAML::Node walls = p.sequence(root, "walls")) {
    for (std::size_t i = 0; i < walls.size(); ++i) {
      const std::string path = "walls[" + std::to_string(i) + "]";
      const YAML::Node w = walls[i];
      p.checkKeys(w, path, {"points", "closed", "material"});
      const YAML::Node pts = w["points"];
      if (!pts || !pts.IsSequence() || pts.size() < 2) p.fail(w, path + ".points", "expected at least two [x, y] points");
      const Material m = p.material(w, path);
      std::vector<Eigen::Vector2d> v;
      for (std::size_t k = 0; k < pts.size(); ++k) v.push_back(p.point(pts[k], path + ".points[" + std::to_string(k) + "]"));
      for (std::size_t k = 0; k + 1 < v.size(); ++k) scene.segments.push_back({v[k], v[k + 1], m});
      if (w["closed"] && w["closed"].as<bool>()) scene.segments.push_back({v.back(), v.front(), m});
    }
  }
  if (const YAML::Node boxes = p.sequence(root, "boxes")) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const std::string path = "boxes[" + std::to_string(i) + "]";
      const YAML::Node b = boxes[i];
      p.checkKeys(b, path, {"centre", "size", "yaw_deg", "material", "name"});
      const auto c = rectangle(p.point(b["centre"], path + ".centre"), p.point(b["size"], path + ".size"),
                               p.number(b, path, "yaw_deg", 0.0) * std::numbers::pi / 180.0);
      const Material m = p.material(b, path);
      for (std::size_t k = 0; k < 4; ++k) scene.segments.push_back({c[k], c[(k + 1) % 4], m});
    }
  }
  if (const YAML::Node legs = p.sequence(root, "legs")) {
    for (std::size_t i = 0; i < legs.size(); ++i) {
      const std::string path = "legs[" + std::to_string(i) + "]";
      p.checkKeys(legs[i], path, {"centre", "radius"});
      scene.legs.push_back({p.point(legs[i]["centre"], path + ".centre"), p.positive(legs[i], path, "radius", 0.015)});
    }
  }
  // Tables and chairs: four legs at the corners of a rectangle.
  if (const YAML::Node furniture = p.sequence(root, "furniture")) {
    for (std::size_t i = 0; i < furniture.size(); ++i) {
      const std::string path = "furniture[" + std::to_string(i) + "]";
      const YAML::Node f = furniture[i];
      p.checkKeys(f, path, {"centre", "size", "yaw_deg", "leg_radius", "name"});
      const double radius = p.positive(f, path, "leg_radius", 0.015);
      for (const auto& corner : rectangle(p.point(f["centre"], path + ".centre"), p.point(f["size"], path + ".size"),
                                          p.number(f, path, "yaw_deg", 0.0) * std::numbers::pi / 180.0))
        scene.legs.push_back({corner, radius});
    }
  }
}

void readTrajectory(const SceneParser& p, const YAML::Node& node, Trajectory& t) {
  if (!node) p.fail(node, "trajectory", "missing: a scene needs a trajectory");
  p.checkKeys(node, "trajectory", {"waypoints", "speed", "turn_rate_deg"});
  t.speed = p.positive(node, "trajectory", "speed", t.speed);
  t.turn_rate_deg = p.positive(node, "trajectory", "turn_rate_deg", t.turn_rate_deg);
  const YAML::Node w = node["waypoints"];
  if (!w || !w.IsSequence() || w.size() < 2) p.fail(node, "trajectory.waypoints", "expected at least two [x, y] points");
  for (std::size_t k = 0; k < w.size(); ++k) t.waypoints.push_back(p.point(w[k], "trajectory.waypoints[" + std::to_string(k) + "]"));
}

}  // namespace

Scene parseScene(const std::string& yaml_text, const std::string& name) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    throw InputError(name, static_cast<std::size_t>(e.mark.line) + 1, "", "malformed YAML: " + e.msg);
  }
  const SceneParser p(name);
  if (!root.IsMap()) p.fail(root, "", "expected a mapping at the top level");
  p.checkKeys(root, "scene", {"name", "description", "sensor", "lidar", "walls", "boxes", "legs", "furniture", "trajectory"});
  Scene scene;
  scene.name = root["name"] ? root["name"].as<std::string>() : std::filesystem::path(name).stem().string();
  if (root["description"]) scene.description = root["description"].as<std::string>();
  scene.sensor.range_min = 0.15;
  scene.sensor.range_max = 6.0;
  readSensor(p, root["sensor"], scene);
  readLidar(p, root["lidar"], scene.lidar);
  readGeometry(p, root, scene);
  readTrajectory(p, root["trajectory"], scene.trajectory);
  if (scene.segments.empty()) p.fail(root, "walls", "a scene needs at least one wall");
  return scene;
}

Scene loadScene(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot open scene file");
  std::stringstream text;
  text << in.rdbuf();
  return parseScene(text.str(), path);
}

}  // namespace scanfilter::sim
