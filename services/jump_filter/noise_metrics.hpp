#pragma once
#include <prometheus/gauge.h>

#include "scanfilter/dds/service_metrics.hpp"
#include "scanfilter/jump_filter_params.hpp"

namespace scanfilter::jump_service {

// The range-noise model step 1 judges with (docs/beyond-the-paper.md, 18), on
// the service's endpoint: σ(d) = base + quadratic·d², each term the larger
// of the measured and the configured one. A base far above the
// sensor's data sheet says its returns are noisier than it claims (a dirty
// window, a failing unit), and step 1 is keeping more of what it would cut.
class NoiseMetrics {
 public:
  explicit NoiseMetrics(dds_io::ServiceMetrics& metrics);

  // Called from the reader's thread after each scan; Gauge::Set is atomic.
  void judgedWith(const RangeNoiseModel& model) {
    base_.Set(model.base);
    quadratic_.Set(model.quadratic);
  }

 private:
  prometheus::Gauge& base_;
  prometheus::Gauge& quadratic_;
};

}  // namespace scanfilter::jump_service
