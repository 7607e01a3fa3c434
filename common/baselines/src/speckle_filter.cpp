#include "scanfilter/baselines/speckle_filter.hpp"

#include <cmath>

namespace scanfilter::baselines {

SpeckleFilter::SpeckleFilter(const SpeckleParams& params) : params_(params) {}

bool SpeckleFilter::distanceWindowValid(const Scan& scan, std::size_t i) const {
  if (!scan.hasReturn(i)) return false;
  const auto window = static_cast<std::size_t>(params_.filter_window);
  for (std::size_t k = 1; k < window && i + k < scan.size(); ++k) {
    if (!scan.hasReturn(i + k) || std::abs(scan.ranges[i + k] - scan.ranges[i]) > params_.max_range_difference)
      return false;
  }
  return true;
}

bool SpeckleFilter::euclideanWindowValid(const Scan& scan, std::size_t i) const {
  const int window = params_.filter_window;
  const auto n = static_cast<std::ptrdiff_t>(scan.size());
  const double r1 = scan.ranges[i];
  int found = 0;
  for (int y = -window; y <= window && found < window; ++y) {
    const std::ptrdiff_t j = static_cast<std::ptrdiff_t>(i) + y;
    if (j < 0 || j >= n || y == 0 || !scan.hasReturn(static_cast<std::size_t>(j))) continue;
    const double r2 = scan.ranges[static_cast<std::size_t>(j)];
    // Law of cosines: the chord between two returns y beams apart.
    const double d = std::sqrt(r1 * r1 + r2 * r2 - 2.0 * r1 * r2 * std::cos(y * scan.angle_increment));
    if (d <= params_.max_range_difference) ++found;  // NaN r1: never
  }
  return found >= window;
}

void SpeckleFilter::apply(const Scan& scan, const SensorInfo& /*sensor*/, std::span<std::uint8_t> labels) {
  labelReturns(scan, labels);
  const std::size_t n = scan.size();
  const auto window = static_cast<std::size_t>(params_.filter_window);
  kept_.assign(n, 0);
  for (std::size_t i = 0; i + window <= n; ++i) {
    const bool valid = params_.mode == SpeckleMode::kDistance ? distanceWindowValid(scan, i) : euclideanWindowValid(scan, i);
    for (std::size_t k = i; k < i + window; ++k) kept_[k] |= valid || scan.ranges[k] > params_.max_range;
  }
  for (std::size_t i = 0; i < n; ++i)
    if (scan.hasReturn(i) && !kept_[i]) labels[i] = static_cast<std::uint8_t>(PointCode::kJump);
}

}  // namespace scanfilter::baselines
