#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "scanfilter/input_error.hpp"
#include "scanfilter/sim/scene.hpp"
#include "scanfilter/sim/tour_clearance.hpp"
#include "scanfilter/yaml_section.hpp"
#include "yaml_sections.hpp"

namespace scanfilter::sim {

namespace {

Eigen::Vector2d rotate(const Eigen::Vector2d& v, double yaw) {
  return {std::cos(yaw) * v.x() - std::sin(yaw) * v.y(), std::sin(yaw) * v.x() + std::cos(yaw) * v.y()};
}

// Corners of a rectangle of `size` centred at `centre`, turned by `yaw`.
std::array<Eigen::Vector2d, 4> rectangle(const Eigen::Vector2d& centre, const Eigen::Vector2d& size, double yaw) {
  const Eigen::Vector2d h = size / 2.0;
  return {centre + rotate({-h.x(), -h.y()}, yaw), centre + rotate({h.x(), -h.y()}, yaw),
          centre + rotate({h.x(), h.y()}, yaw), centre + rotate({-h.x(), h.y()}, yaw)};
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
      if (w["closed"] && p.boolean(w["closed"], path + ".closed")) scene.segments.push_back({v.back(), v.front(), m});
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
  p.checkKeys(node, "trajectory", {"waypoints", "speed", "turn_rate_deg", "robot_radius"});
  t.speed = p.positive(node, "trajectory", "speed", t.speed);
  t.robot_radius = p.positive(node, "trajectory", "robot_radius", t.robot_radius);
  t.turn_rate_deg = p.positive(node, "trajectory", "turn_rate_deg", t.turn_rate_deg);
  const YAML::Node w = node["waypoints"];
  if (!w || !w.IsSequence() || w.size() < 2) p.fail(node, "trajectory.waypoints", "expected at least two [x, y] points");
  for (std::size_t k = 0; k < w.size(); ++k) t.waypoints.push_back(p.point(w[k], "trajectory.waypoints[" + std::to_string(k) + "]"));
}

// A tour the robot's body does not fit along is an error, not a scene: it
// would scan from inside a wall or a stool (tour_clearance.hpp).
void checkTourFits(const SceneParser& p, const YAML::Node& trajectory, const Scene& scene) {
  const auto obstruction = firstObstruction(scene);
  if (!obstruction) return;
  const std::size_t k = obstruction->from_waypoint;
  std::ostringstream problem;
  problem << std::fixed << std::setprecision(3) << "the way from here to waypoints[" << k + 1 << "] passes "
          << obstruction->clearance << " m from " << obstruction->obstacle << ", nearer than trajectory.robot_radius ("
          << scene.trajectory.robot_radius << " m): the robot would drive through it";
  p.fail(trajectory["waypoints"][k], "trajectory.waypoints[" + std::to_string(k) + "]", problem.str());
}

}  // namespace

Scene parseScene(const std::string& yaml_text, const std::string& name) {
  const YAML::Node root = parseYaml(yaml_text, name);
  const SceneParser p(name);
  if (!root.IsMap()) p.fail(root, "", "expected a mapping at the top level");
  p.checkKeys(root, "scene",
              {"name", "description", "sensor", "lidar", "odometry", "walls", "boxes", "legs", "furniture", "trajectory"});
  Scene scene;
  scene.name = root["name"] ? p.text(root["name"], "name") : std::filesystem::path(name).stem().string();
  if (root["description"]) scene.description = p.text(root["description"], "description");
  scene.sensor.range_min = 0.15;
  scene.sensor.range_max = 6.0;
  readSensor(p, root["sensor"], scene, true);
  readLidar(p, root["lidar"], scene.lidar);
  readOdometry(p, root["odometry"], scene.odometry);
  readGeometry(p, root, scene);
  readTrajectory(p, root["trajectory"], scene.trajectory);
  checkTourFits(p, root["trajectory"], scene);
  if (scene.segments.empty()) p.fail(root, "walls", "a scene needs at least one wall");
  return scene;
}

Scene loadScene(const std::string& path) { return parseScene(readConfigText(path), path); }

}  // namespace scanfilter::sim
