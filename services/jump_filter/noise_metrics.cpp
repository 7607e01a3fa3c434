#include "noise_metrics.hpp"

namespace scanfilter::jump_service {

namespace {

prometheus::Gauge& gauge(dds_io::ServiceMetrics& metrics, const char* name, const char* help) {
  return prometheus::BuildGauge().Name(name).Help(help).Register(metrics.registry()).Add({{"service", "jump_filter"}});
}

}  // namespace

NoiseMetrics::NoiseMetrics(dds_io::ServiceMetrics& metrics)
    : base_(gauge(metrics, "scanfilter_range_noise_base_metres",
                  "Range noise sigma at zero range step 1 judges with (measured where above the configured)")),
      quadratic_(gauge(metrics, "scanfilter_range_noise_quadratic_per_metre",
                       "Growth of the range noise sigma with the square of the range, metres per square metre")) {}

}  // namespace scanfilter::jump_service
