#pragma once
#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scanfilter/sensor_info.hpp"
#include "scanfilter/two_step_filter.hpp"

namespace scanfilter {

// The filter's configuration as written in YAML (config/filter.yaml documents
// every key). Values marked `auto` there come from the sensor at run time.
struct FilterConfig {
  TwoStepFilterParams params;
  std::optional<double> angular_accuracy_deg;  // unset: the log header's
  std::optional<double> d_min;                 // unset: the sensor's range_min
  std::optional<double> d_max;                 // unset: the sensor's range_max
  // obs_th counts points, and a surface puts more of them in a cell the finer
  // the angular step: obs_th is given for this step (degrees) and scaled to
  // the sensor's (rounded). 0: obs_th as given, whatever the sensor.
  double obstacle_threshold_reference_deg = 1.0;
  // A surface, or the trail of mixed returns behind an edge, puts more
  // returns near a point the finer the step, so free_space_veto_count (a
  // count of other frames' returns near a point) is given for this step
  // (degrees) and scaled to the sensor's (rounded, at least 1). 0: as given.
  double free_space_veto_reference_deg = 1.0;
  // penetration_filter.surface_memory.sparse_surfaces.support_reference_deg:
  // a pane's or a mirror's returns, and the reflections that line up behind
  // them, fill more cells the finer the step: the sparse surfaces' support
  // (min_neighbours, min_cells) is given for this step (degrees) and scaled
  // by the square root of the sensor's beams per it (rounded): a cell counts
  // once however many returns it holds (docs/beyond-the-paper.md, 29). 0: as given.
  double sparse_support_reference_deg = 1.0;

  // Parameters for one sensor, with every `auto` value filled in.
  TwoStepFilterParams resolve(const SensorInfo& sensor) const;
};

// Loads and validates a filter config; throws InputError naming the file, the
// line and the key. Keys left out keep their defaults; unknown keys are errors
// (a misspelt key would otherwise be silently ignored).
FilterConfig loadFilterConfig(const std::string& path);
FilterConfig parseFilterConfig(const std::string& yaml_text, const std::string& name);
// The same from an already parsed document whose top level holds only the
// jump_filter and penetration_filter sections.
FilterConfig filterConfigFromYaml(const YAML::Node& root, const std::string& name);

}  // namespace scanfilter
