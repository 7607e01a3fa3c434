#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

// Anything that labels the beams of a scan stream: the two-step filter and the
// baselines it is compared with (common/include/scanfilter/baselines/).
// Scans arrive in time order; filters that keep recent frames keep them here.
class ScanFilter {
 public:
  virtual ~ScanFilter() = default;
  // Writes one PointCode per beam: kNoReturn for beams without a return,
  // kValid for kept ones, kJump or kMisdetected for removed ones.
  virtual void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) = 0;
};

// Labels every beam kValid or kNoReturn: where each filter starts.
inline void labelReturns(const Scan& scan, std::span<std::uint8_t> labels) {
  for (std::size_t i = 0; i < scan.size(); ++i)
    labels[i] = static_cast<std::uint8_t>(scan.hasReturn(i) ? PointCode::kValid : PointCode::kNoReturn);
}

}  // namespace scanfilter
