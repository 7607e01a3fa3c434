#pragma once
#include <cstdint>
#include <memory>
#include <span>

#include "scanfilter/implementation.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/penetration_filter.hpp"

namespace scanfilter {

// Beyond the paper (algorithm-notes.md): step 1 deletes every cluster of one or
// two beams, so a thin leg is lost whatever the parameters. A jump point is
// restored when its cell was hit often by recent frames: persistent evidence a
// jump point (it moves with the viewpoint) does not leave. Off = the paper.
struct PersistenceRescueParams {
  bool enabled = false;
  int min_count = 8;  // grid count (points of cached frames) the point's cell needs
};

struct TwoStepFilterParams {
  bool jump_enabled = true;
  bool penetration_enabled = true;
  JumpFilterParams jump;
  PenetrationFilterParams penetration;
  PersistenceRescueParams rescue;
};

// Both steps in order; one code per beam (point_code.hpp). A beam that both
// steps would remove keeps step 1's code.
class TwoStepFilter {
 public:
  TwoStepFilter(const TwoStepFilterParams& params, Implementation impl);

  void apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels);
  const PenetrationFilter& penetration() const { return *penetration_; }
  const TwoStepFilterParams& params() const { return params_; }

 private:
  void rescuePersistentPoints(const Scan& scan, const SensorInfo& sensor,
                              std::span<std::uint8_t> labels);

  TwoStepFilterParams params_;
  std::unique_ptr<JumpFilter> jump_;
  std::unique_ptr<PenetrationFilter> penetration_;
};

}  // namespace scanfilter
