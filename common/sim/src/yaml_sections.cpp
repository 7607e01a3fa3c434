#include "yaml_sections.hpp"

#include <numbers>

namespace scanfilter::sim {

namespace {
constexpr double kDegToRad = std::numbers::pi / 180.0;
// Bound on the footprint rays a scene or sensor file may give: far beyond
// any useful sampling (beams: kMaxSimulatedBeams).
constexpr int kMaxFootprintRays = 1000;

RangeMixing mixing(const SceneParser& p, const YAML::Node& map, RangeMixing fallback) {
  const YAML::Node v = map["mixing"];
  if (!v) return fallback;
  const std::string m = p.text(v, "lidar.mixing");
  if (m == "linear") return RangeMixing::kLinear;
  if (m == "inverse_depth") return RangeMixing::kInverseDepth;
  p.fail(v, "lidar.mixing", "expected linear or inverse_depth, got \"" + m + "\"");
}
}  // namespace

void readSensor(const SceneParser& p, const YAML::Node& node, Scene& scene, bool with_mount) {
  if (!node) return;
  std::set<std::string> keys = {"range_min", "range_max", "angular_accuracy_deg", "beams", "rate_hz"};
  if (with_mount) keys.insert({"mount", "direction"});
  p.checkKeys(node, "sensor", keys);
  SensorInfo& s = scene.sensor;
  if (const YAML::Node m = node["mount"]) {
    s.mount = p.mount(m, "sensor.mount");
  }
  if (const YAML::Node d = node["direction"]) {
    const auto text = p.text(d, "sensor.direction");
    if (text != "cw" && text != "ccw") p.fail(d, "sensor.direction", "expected cw or ccw");
    s.direction = text == "cw" ? BeamDirection::kCw : BeamDirection::kCcw;
  }
  s.range_min = p.number(node, "sensor", "range_min", s.range_min);
  s.range_max = p.positive(node, "sensor", "range_max", s.range_max);
  if (!(s.range_max > s.range_min)) p.fail(node["range_max"], "sensor.range_max", "must exceed range_min");
  s.angular_accuracy_deg = p.positive(node, "sensor", "angular_accuracy_deg", s.angular_accuracy_deg);
  scene.lidar.beams = p.count(node, "sensor", "beams", scene.lidar.beams, kMaxSimulatedBeams);
  scene.lidar.rate_hz = p.positive(node, "sensor", "rate_hz", scene.lidar.rate_hz);
}

void readLidar(const SceneParser& p, const YAML::Node& node, LidarModel& m) {
  if (!node) return;
  p.checkKeys(node, "lidar",
              {"mixing", "range_resolution", "noise_sigma_base", "noise_sigma_quadratic", "beam_divergence_mrad",
               "exit_aperture", "exposure_sweep", "footprint_rays", "grazing_angle_deg", "grazing_probability",
               "grazing_error_max", "junction_radius", "junction_probability", "junction_error_max", "jump_min_error",
               "smooth_lobe_width_deg", "smooth_diffuse_return", "glass_lobe_width_deg", "glass_diffuse_return",
               "glass_refractive_index", "dropout_probability"});
  const std::string s = "lidar";
  m.mixing = mixing(p, node, m.mixing);
  m.range_resolution = p.positive(node, s, "range_resolution", m.range_resolution);
  m.noise_sigma_base = p.number(node, s, "noise_sigma_base", m.noise_sigma_base);
  m.noise_sigma_quadratic = p.number(node, s, "noise_sigma_quadratic", m.noise_sigma_quadratic);
  m.beam_divergence_mrad = p.number(node, s, "beam_divergence_mrad", m.beam_divergence_mrad);
  m.exit_aperture = p.number(node, s, "exit_aperture", m.exit_aperture);
  m.exposure_sweep = p.number(node, s, "exposure_sweep", m.exposure_sweep);
  m.footprint_rays = p.count(node, s, "footprint_rays", m.footprint_rays, kMaxFootprintRays);
  m.grazing_angle_deg = p.number(node, s, "grazing_angle_deg", m.grazing_angle_deg);
  m.grazing_probability = p.probability(node, s, "grazing_probability", m.grazing_probability);
  m.grazing_error_max = p.number(node, s, "grazing_error_max", m.grazing_error_max);
  m.junction_radius = p.number(node, s, "junction_radius", m.junction_radius);
  m.junction_probability = p.probability(node, s, "junction_probability", m.junction_probability);
  m.junction_error_max = p.number(node, s, "junction_error_max", m.junction_error_max);
  m.jump_min_error = p.positive(node, s, "jump_min_error", m.jump_min_error);
  m.smooth.lobe_width_deg = p.number(node, s, "smooth_lobe_width_deg", m.smooth.lobe_width_deg);
  m.smooth.diffuse_return = p.probability(node, s, "smooth_diffuse_return", m.smooth.diffuse_return);
  m.glass.lobe_width_deg = p.number(node, s, "glass_lobe_width_deg", m.glass.lobe_width_deg);
  m.glass.diffuse_return = p.probability(node, s, "glass_diffuse_return", m.glass.diffuse_return);
  m.glass_refractive_index = p.number(node, s, "glass_refractive_index", m.glass_refractive_index);
  if (!(m.glass_refractive_index >= 1.0)) p.fail(node["glass_refractive_index"], "lidar.glass_refractive_index", "expected a value >= 1");
  m.dropout_probability = p.probability(node, s, "dropout_probability", m.dropout_probability);
}

void readOdometry(const SceneParser& p, const YAML::Node& node, OdometryDrift& drift) {
  if (!node) return;
  p.checkKeys(node, "odometry", {"scale_error", "heading_drift_deg_per_m"});
  drift.scale_error = p.number(node, "odometry", "scale_error", drift.scale_error);
  if (node["heading_drift_deg_per_m"])
    drift.heading_drift_per_m = p.number(node, "odometry", "heading_drift_deg_per_m", 0.0) * kDegToRad;
}

}  // namespace scanfilter::sim
