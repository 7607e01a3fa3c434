#include "scanfilter/sim/range_mixing.hpp"

#include <limits>

namespace scanfilter::sim {

double mixRanges(RangeMixing mixing, const std::vector<PartialReturn>& parts) {
  double weights = 0.0, sum = 0.0;
  for (const auto& p : parts) {
    weights += p.weight;
    sum += p.weight * (mixing == RangeMixing::kLinear ? p.range : 1.0 / p.range);
  }
  if (!(weights > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double mean = sum / weights;
  return mixing == RangeMixing::kLinear ? mean : 1.0 / mean;
}

}  // namespace scanfilter::sim
