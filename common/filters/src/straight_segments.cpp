#include "scanfilter/straight_segments.hpp"

#include <cmath>
#include <cstddef>

#include <Eigen/Eigenvalues>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

namespace {

// `whole`: the run that `piece` was split from. The ends a piece shares with
// it are marked as such; whether the frame saw past them is for the caller.
void fitPiece(std::span<const Eigen::Vector2d> piece, std::span<const Eigen::Vector2d> whole,
              const StraightSegmentParams& params, std::vector<StraightSegment>& out) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& p : piece) mean += p;
  mean /= static_cast<double>(piece.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const auto& p : piece) scatter += (p - mean) * (p - mean).transpose();
  // The line's direction: the scatter's larger eigenvector (eigenvalues ascend).
  const Eigen::Vector2d direction = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(scatter).eigenvectors().col(1);
  const Eigen::Vector2d a = mean + direction * direction.dot(piece.front() - mean);
  const Eigen::Vector2d b = mean + direction * direction.dot(piece.back() - mean);
  const double length = (b - a).norm();
  if (!(length > 0.0) || length < params.min_length) return;  // a segment has a direction
  out.push_back({a, b, piece.data() == whole.data(), piece.data() + piece.size() == whole.data() + whole.size()});
}

void splitAndFit(std::span<const Eigen::Vector2d> piece, std::span<const Eigen::Vector2d> whole,
                 const StraightSegmentParams& params, std::vector<StraightSegment>& out) {
  if (static_cast<int>(piece.size()) < params.min_returns) return;
  std::size_t farthest = 0;
  double farthest_off = 0.0;
  for (std::size_t k = 1; k + 1 < piece.size(); ++k) {
    const double off = distanceToLine(piece[k], piece.front(), piece.back());
    if (off > farthest_off) farthest_off = off, farthest = k;
  }
  if (farthest_off > params.max_deviation) {  // a corner: both sides keep it
    splitAndFit(piece.subspan(0, farthest + 1), whole, params, out);
    splitAndFit(piece.subspan(farthest), whole, params, out);
    return;
  }
  fitPiece(piece, whole, params, out);
}

// Where a full turn's runs start: a beam whose neighbour before it (across
// the seam for the first) does not join it (no usable return on either, or
// too far apart). 0 when every beam joins the next.
std::size_t firstBeamAfterABreak(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                                 double spacing_sq) {
  const std::size_t n = points.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t before = (i + n - 1) % n;
    if (!usable[i] || !usable[before] || (points[i] - points[before]).squaredNorm() > spacing_sq) return i;
  }
  return 0;
}

}  // namespace

std::vector<StraightSegment> straightSegments(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                                              const Eigen::Vector2d& origin, const StraightSegmentParams& params,
                                              bool full_turn) {
  std::vector<StraightSegment> out;
  std::vector<Eigen::Vector2d> run;
  const auto n = static_cast<std::ptrdiff_t>(points.size());
  const double spacing_sq = params.max_spacing * params.max_spacing;
  // Beams are walked from `start`, in positions 0..n-1; on a full turn the
  // walk wraps, so that a surface across the seam is one run.
  const auto start =
      full_turn ? static_cast<std::ptrdiff_t>(firstBeamAfterABreak(points, usable, spacing_sq)) : std::ptrdiff_t{0};
  const auto beamAt = [&](std::ptrdiff_t position) { return static_cast<std::size_t>((start + position) % n); };
  std::ptrdiff_t first = 0;  // the run's first position
  const auto seenPast = [&](std::ptrdiff_t position, const Eigen::Vector2d& end) {
    if (!full_turn && (position < 0 || position >= n)) return false;  // a partial scan starts at 0
    const std::size_t j = beamAt((position + n) % n);
    return usable[j] && (points[j] - origin).norm() > (end - origin).norm() + params.end_step;
  };
  const auto finishRun = [&](std::ptrdiff_t end) {  // the run is positions [first, end)
    const std::size_t before = out.size();
    splitAndFit(run, run, params, out);
    for (std::size_t k = before; k < out.size(); ++k) {
      out[k].a_seen_past = out[k].a_seen_past && seenPast(first - 1, run.front());
      out[k].b_seen_past = out[k].b_seen_past && seenPast(end, run.back());
    }
    run.clear();
  };
  for (std::ptrdiff_t position = 0; position < n; ++position) {
    const std::size_t i = beamAt(position);
    const bool joins = usable[i] && (run.empty() || (points[i] - run.back()).squaredNorm() <= spacing_sq);
    if (!joins && !run.empty()) finishRun(position);
    if (!usable[i]) continue;
    if (run.empty()) first = position;
    run.push_back(points[i]);
  }
  if (!run.empty()) finishRun(n);
  return out;
}

}  // namespace scanfilter
