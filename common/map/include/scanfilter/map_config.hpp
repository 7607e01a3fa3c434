#pragma once
#include <yaml-cpp/yaml.h>

#include "scanfilter/occupancy_grid.hpp"
#include "scanfilter/yaml_section.hpp"

namespace scanfilter {

// Reads the `map:` section (config/map_publisher.yaml documents every key).
inline OccupancyGridParams readMapParams(const YAML::Node& root, const std::string& file) {
  OccupancyGridParams p;
  YamlSection s(root, "map", file);
  s.read("resolution", p.resolution);
  s.read("hit_probability", p.hit_probability);
  s.read("miss_probability", p.miss_probability);
  s.read("clamp_min", p.clamp_min);
  s.read("clamp_max", p.clamp_max);
  s.read("occupied_threshold", p.occupied_threshold);
  s.read("free_threshold", p.free_threshold);
  s.read("clear_on_no_return", p.clear_on_no_return);
  s.read("no_return_clear_range", p.no_return_clear_range);
  s.requireRange("resolution", p.resolution, 0.005, 10.0, "0.005-10 (m)");
  s.requireRange("hit_probability", p.hit_probability, 0.5001, 0.9999, "0.5 < p < 1");
  s.requireRange("miss_probability", p.miss_probability, 0.0001, 0.4999, "0 < p < 0.5");
  s.requireRange("clamp_min", p.clamp_min, 0.0001, 0.4999, "0 < p < 0.5");
  s.requireRange("clamp_max", p.clamp_max, 0.5001, 0.9999, "0.5 < p < 1");
  s.requireRange("occupied_threshold", p.occupied_threshold, 0.5, 1.0, "0.5-1");
  s.requireRange("free_threshold", p.free_threshold, 0.0, 0.5, "0-0.5");
  s.requireRange("no_return_clear_range", p.no_return_clear_range, 0.0, 1e3, "0-1000 (m)");
  s.rejectUnknownKeys();
  return p;
}

}  // namespace scanfilter
