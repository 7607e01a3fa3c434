#include "scanfilter/two_step_filter.hpp"

#include "scanfilter/point_code.hpp"

namespace scanfilter {

TwoStepFilter::TwoStepFilter(const TwoStepFilterParams& params, Implementation impl)
    : params_(params),
      jump_(makeJumpFilter(params.jump, impl)),
      penetration_(makePenetrationFilter(params.penetration, impl)) {}

void TwoStepFilter::apply(const Scan& scan, const SensorInfo& sensor,
                          std::span<std::uint8_t> labels) {
  if (params_.jump_enabled) {
    jump_->apply(scan, sensor, labels);
  } else {
    labelReturns(scan, labels);
  }
  if (params_.penetration_enabled) penetration_->apply(scan, sensor, labels);
}

}  // namespace scanfilter
