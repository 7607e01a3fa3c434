#include "scanfilter/off_surface_check.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/wrapped_returns.hpp"

namespace scanfilter {

void OffSurfaceCheck::apply(std::span<const Eigen::Vector2d> points, std::span<const double> ranges, bool full_turn,
                            std::span<const std::uint8_t> spared, std::span<std::uint8_t> labels) {
  if (!params_.off_surface_check) return;
  const WrappedReturns returns(points, ranges, full_turn);
  const auto n = returns.size();
  // A side condemns p when its three nearest returns lie on one line (so the
  // line is a surface, not clutter) and p lies off it. Judged on the step-1
  // labels as they were: marking as we go would let one removal change its
  // neighbours' verdicts, and the order would matter.
  const auto sideCondemns = [&](std::int64_t i, int step, double tol) {
    const Eigen::Vector2d* near = returns.at(i + step);
    const Eigen::Vector2d* mid = returns.at(i + 2 * step);
    const Eigen::Vector2d* far = returns.at(i + 3 * step);
    if (!near || !mid || !far) return false;  // no line on this side: nothing to judge by
    // Most returns lie on the line: test p first, the straightness only then.
    return isFartherFromLineThan(points[static_cast<std::size_t>(i)], *mid, *near, tol) &&
           !isFartherFromLineThan(*far, *mid, *near, tol);
  };
  marked_.clear();
  for (std::int64_t i = 0; i < n; ++i) {
    const auto beam = static_cast<std::size_t>(i);
    if (labels[beam] != static_cast<std::uint8_t>(PointCode::kValid) || spared[beam]) continue;
    const double tol = offSurfaceTolerance(params_, ranges[static_cast<std::size_t>(i)]);
    if (sideCondemns(i, -1, tol) && sideCondemns(i, +1, tol)) marked_.push_back(static_cast<std::uint32_t>(i));
  }
  for (auto i : marked_) labels[i] = static_cast<std::uint8_t>(PointCode::kJump);
}

}  // namespace scanfilter
