#include "scanfilter/baselines/scan_shadows_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace scanfilter::baselines {

ScanShadowsFilter::ScanShadowsFilter(const ScanShadowsParams& params) : params_(params) {}

bool ScanShadowsFilter::isShadowEdge(const Scan& scan, std::size_t i, std::size_t j) const {
  const double included = (static_cast<double>(j) - static_cast<double>(i)) * scan.angle_increment;
  const double ri = scan.ranges[i], rj = scan.ranges[j];
  const double angle_deg = std::abs(std::atan2(rj * std::sin(included), ri - rj * std::cos(included))) * 180.0 /
                           std::numbers::pi;
  // NaN (a beam without a return) fails both comparisons: never an edge.
  return angle_deg < params_.min_angle_deg || angle_deg > params_.max_angle_deg;
}

void ScanShadowsFilter::apply(const Scan& scan, const SensorInfo& /*sensor*/, std::span<std::uint8_t> labels) {
  labelReturns(scan, labels);
  const auto n = static_cast<std::ptrdiff_t>(scan.size());
  const auto removed = static_cast<std::uint8_t>(PointCode::kJump);
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    for (std::ptrdiff_t j = std::max<std::ptrdiff_t>(0, i - params_.window);
         j <= std::min<std::ptrdiff_t>(n - 1, i + params_.window); ++j) {
      if (j == i || !isShadowEdge(scan, static_cast<std::size_t>(i), static_cast<std::size_t>(j))) continue;
      for (std::ptrdiff_t k = std::max<std::ptrdiff_t>(0, i - params_.neighbors);
           k <= std::min<std::ptrdiff_t>(n - 1, i + params_.neighbors); ++k) {
        if (scan.ranges[i] < scan.ranges[k]) labels[k] = removed;
      }
      if (params_.remove_shadow_start_point) labels[i] = removed;
    }
  }
}

}  // namespace scanfilter::baselines
