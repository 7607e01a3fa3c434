#pragma once
#include <functional>
#include <memory>

#include "scanfilter/filter_config.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter::dds_io {

// A filter built for the sensor of the scan at hand: the config's `auto` and
// sensor-scaled values (Δθ, range limits, obs_th) come from the sensor, so
// the filter is rebuilt, its state dropped, when another sensor's scans come.
template <typename Filter>
class PerSensorFilter {
 public:
  using Make = std::function<std::unique_ptr<Filter>(const TwoStepFilterParams&)>;

  PerSensorFilter(FilterConfig config, Make make) : config_(std::move(config)), make_(std::move(make)) {}

  Filter& forSensor(const SensorInfo& sensor) {
    if (!filter_ || !sameSensor(sensor, sensor_)) {
      filter_ = make_(config_.resolve(sensor));
      sensor_ = sensor;
    }
    return *filter_;
  }
  // The current filter (null before the first scan).
  const Filter* current() const { return filter_.get(); }

 private:
  static bool sameSensor(const SensorInfo& a, const SensorInfo& b) {
    return a.range_min == b.range_min && a.range_max == b.range_max && a.angular_accuracy_deg == b.angular_accuracy_deg;
  }

  FilterConfig config_;
  Make make_;
  SensorInfo sensor_;
  std::unique_ptr<Filter> filter_;
};

}  // namespace scanfilter::dds_io
