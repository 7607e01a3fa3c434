#include "scanfilter/off_surface_check.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/point_code.hpp"

namespace scanfilter {

bool OffSurfaceCheck::isOffLine(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                double tol) {
  // distanceToLine(p, a, b) > tol without the square root (the same decision).
  const Eigen::Vector2d d = b - a;
  const double length_sq = d.squaredNorm();
  if (length_sq == 0.0) return (p - a).squaredNorm() > tol * tol;
  const double cross = d.x() * (p.y() - a.y()) - d.y() * (p.x() - a.x());
  return cross * cross > tol * tol * length_sq;
}

double OffSurfaceCheck::tolerance(double range) const {
  const double sigma = params_.noise_sigma_base + params_.noise_sigma_quadratic * range * range;
  return std::max(params_.off_surface_min, params_.off_surface_sigmas * sigma);
}

void OffSurfaceCheck::apply(std::span<const Eigen::Vector2d> points, std::span<const double> ranges, bool full_turn,
                            std::span<std::uint8_t> labels) {
  if (!params_.off_surface_check) return;
  const auto n = static_cast<std::int64_t>(points.size());
  const auto at = [&](std::int64_t k) -> const Eigen::Vector2d* {
    if (full_turn) k += k < 0 ? n : (k >= n ? -n : 0);  // offsets are a few beams, never a whole turn
    if (k < 0 || k >= n || ranges[static_cast<std::size_t>(k)] != ranges[static_cast<std::size_t>(k)]) return nullptr;
    return &points[static_cast<std::size_t>(k)];
  };
  // A side condemns p when its three nearest returns lie on one line (so the
  // line is a surface, not clutter) and p lies off it. Judged on the step-1
  // labels as they were: marking as we go would let one removal change its
  // neighbours' verdicts, and the order would matter.
  const auto sideCondemns = [&](std::int64_t i, int step, double tol) {
    const Eigen::Vector2d* near = at(i + step);
    const Eigen::Vector2d* mid = at(i + 2 * step);
    const Eigen::Vector2d* far = at(i + 3 * step);
    if (!near || !mid || !far) return false;  // no line on this side: nothing to judge by
    // Most returns lie on the line: test p first, the straightness only then.
    return isOffLine(points[static_cast<std::size_t>(i)], *mid, *near, tol) && !isOffLine(*far, *mid, *near, tol);
  };
  marked_.clear();
  for (std::int64_t i = 0; i < n; ++i) {
    if (labels[static_cast<std::size_t>(i)] != static_cast<std::uint8_t>(PointCode::kValid)) continue;
    const double tol = tolerance(ranges[static_cast<std::size_t>(i)]);
    if (sideCondemns(i, -1, tol) && sideCondemns(i, +1, tol)) marked_.push_back(static_cast<std::uint32_t>(i));
  }
  for (auto i : marked_) labels[i] = static_cast<std::uint8_t>(PointCode::kJump);
}

}  // namespace scanfilter
