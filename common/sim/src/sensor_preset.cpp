#include "scanfilter/sim/sensor_preset.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "builtin_texts.hpp"
#include "scanfilter/yaml_section.hpp"
#include "yaml_sections.hpp"

namespace scanfilter::sim {

namespace {

constexpr double kDegreesPerTurn = 360.0;

void parsePreset(const std::string& yaml_text, const std::string& file, Scene& scene) {
  const YAML::Node root = parseYaml(yaml_text, file);
  const SceneParser p(file);
  if (!root.IsMap()) p.fail(root, "", "expected a mapping at the top level");
  p.checkKeys(root, "sensor preset", {"name", "description", "sensor", "lidar"});
  if (!root["sensor"]) p.fail(root, "sensor", "missing: a sensor preset needs its range limits and beams");
  scene.lidar = LidarModel{};
  readSensor(p, root["sensor"], scene, false);
  readLidar(p, root["lidar"], scene.lidar);
  scene.sensor_preset = root["name"] ? p.text(root["name"], "name") : std::filesystem::path(file).stem().string();
}

}  // namespace

std::vector<std::string> builtinSensorNames() { return builtinNames(builtinSensorTexts()); }

void applySensor(Scene& scene, const std::string& name_or_path) {
  if (const auto text = builtinText(builtinSensorTexts(), name_or_path))
    return parsePreset(*text, "builtin sensor " + name_or_path, scene);
  std::error_code error;  // a name too long is "no such file", not an exception
  if (std::filesystem::exists(name_or_path, error)) return parsePreset(readConfigText(name_or_path), name_or_path, scene);
  throw InputError(name_or_path, 0, "",
                   "no such sensor file, and not a built-in sensor (" + namesList(builtinSensorTexts()) + ")");
}

void setBeams(Scene& scene, int beams) {
  scene.lidar.beams = beams;
  scene.sensor.angular_accuracy_deg = kDegreesPerTurn / beams;
}

Scene sceneWithSensor(const std::string& scene_name, const std::string& sensor, int beams) {
  Scene scene = findScene(scene_name);
  if (!sensor.empty()) applySensor(scene, sensor);
  if (beams > 0) setBeams(scene, beams);
  return scene;
}

}  // namespace scanfilter::sim
