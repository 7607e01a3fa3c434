#include "scanfilter/beam_bundle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace scanfilter {

namespace {
// cos 60°: beams farther off the axis make the band pointless long before.
constexpr double kMinCosOffAxis = 0.5;
// The bound is computed in floating point; the walk re-tests every cell it
// returns, so erring wide costs nothing.
constexpr double kRoundingSlack = 1e-9;
}  // namespace

std::optional<BundleBand> bundleBand(std::span<const BundledBeam> beams, double beam_half_width) {
  if (beams.empty()) return std::nullopt;
  const Eigen::Vector2d sum = beams.front().unit + beams.back().unit;
  const double norm = sum.norm();
  if (!(norm > 0.0)) return std::nullopt;
  const Eigen::Vector2d axis = sum / norm;
  double length = 0.0, spread = 0.0;
  for (const auto& beam : beams) {
    const double along = axis.dot(beam.unit);  // cos a_k
    if (!(along >= kMinCosOffAxis)) return std::nullopt;
    const double off = std::abs(axis.x() * beam.unit.y() - axis.y() * beam.unit.x());  // |sin a_k|
    length = std::max(length, beam.reach * along);
    spread = std::max(spread, beam.reach * off);
  }
  return BundleBand{axis, length + kRoundingSlack, beam_half_width + spread + kRoundingSlack};
}

double fanSpread(const BundledBeam& first, const BundledBeam& last, double max_reach) {
  // The beams between lie at most half the fan's angle f off the bisector:
  // sin(f/2) = |first x last| / |first + last|, cos(f/2) = |first + last| / 2.
  const double sum = (first.unit + last.unit).norm();
  if (!(sum / 2.0 > kMinCosOffAxis)) return std::numeric_limits<double>::infinity();
  const double cross = std::abs(first.unit.x() * last.unit.y() - first.unit.y() * last.unit.x());
  return max_reach * cross / sum;
}

}  // namespace scanfilter
