#pragma once
#include <cstdint>
#include <memory>
#include <span>

#include "scanfilter/implementation.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/scan_filter.hpp"

namespace scanfilter {

struct TwoStepFilterParams {
  bool jump_enabled = true;
  bool penetration_enabled = true;
  JumpFilterParams jump;
  PenetrationFilterParams penetration;
};

// Both steps in order; one code per beam (point_code.hpp). A beam that both
// steps would remove keeps step 1's code.
class TwoStepFilter final : public ScanFilter {
 public:
  TwoStepFilter(const TwoStepFilterParams& params, Implementation impl);

  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) override;
  const PenetrationFilter& penetration() const { return *penetration_; }
  const JumpFilter& jump() const { return *jump_; }
  const TwoStepFilterParams& params() const { return params_; }

 private:
  TwoStepFilterParams params_;
  std::unique_ptr<JumpFilter> jump_;
  std::unique_ptr<PenetrationFilter> penetration_;
};

}  // namespace scanfilter
