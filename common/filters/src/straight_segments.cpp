#include "scanfilter/straight_segments.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

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

// Where a full turn's runs start: the usable return farthest from the usable
// return before it (across the seam for the first), among those that do not
// join it; the widest break, so that a run can go on across any narrower gap
// (straightSegments) without wrapping past the walk's end. 0 when every beam
// joins the next.
std::size_t beamAfterTheWidestBreak(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                                    double spacing_sq) {
  const std::size_t n = points.size();
  std::ptrdiff_t before = -1;  // the last usable return before beam 0, across the seam
  for (std::size_t k = n; k-- > 0;)
    if (usable[k]) {
      before = static_cast<std::ptrdiff_t>(k);
      break;
    }
  if (before < 0) return 0;
  std::size_t widest = 0;
  double widest_sq = -1.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable[i]) continue;
    const std::size_t previous = (i + n - 1) % n;
    const double gap_sq = (points[i] - points[static_cast<std::size_t>(before)]).squaredNorm();
    const bool breaks = !usable[previous] || gap_sq > spacing_sq;
    if (breaks && gap_sq > widest_sq) widest_sq = gap_sq, widest = i;
    before = static_cast<std::ptrdiff_t>(i);
  }
  return widest;
}

// Whether p lies on the line of the run's last returns (min_returns of
// them, or all), within max_deviation, and on beyond its last return: the
// same surface across a gap, not a step to another one.
bool continuesRun(std::span<const Eigen::Vector2d> run, const Eigen::Vector2d& p, const StraightSegmentParams& params) {
  if (run.size() < 2) return false;
  const std::size_t tail = std::min(run.size(), static_cast<std::size_t>(std::max(2, params.min_returns)));
  const Eigen::Vector2d& from = run[run.size() - tail];
  const Eigen::Vector2d& last = run.back();
  return distanceToLine(p, from, last) <= params.max_deviation && (p - last).dot(last - from) > 0.0;
}

}  // namespace

std::vector<StraightSegment> straightSegments(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                                              const Eigen::Vector2d& origin, const StraightSegmentParams& params,
                                              bool full_turn, const SurfaceAcrossGap& surface_across_gap) {
  std::vector<StraightSegment> out;
  std::vector<Eigen::Vector2d> run;
  const auto n = static_cast<std::ptrdiff_t>(points.size());
  const double spacing_sq = params.max_spacing * params.max_spacing;
  // Beams are walked from `start`, in positions 0..n-1; on a full turn the
  // walk wraps, so that a surface across the seam is one run.
  const auto start =
      full_turn ? static_cast<std::ptrdiff_t>(beamAfterTheWidestBreak(points, usable, spacing_sq)) : std::ptrdiff_t{0};
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
  const double gap_sq = params.max_gap * params.max_gap;
  // The position of the return that continues the run across a gap that
  // starts at `position` (the first beam that does not join), or -1.
  const auto acrossGap = [&](std::ptrdiff_t position) -> std::ptrdiff_t {
    if (!surface_across_gap || !(params.max_gap > 0.0)) return -1;
    const Eigen::Vector2d to_last = run.back() - origin;
    const double last_range = to_last.norm();
    // A return within max_gap of the last lies within this angle of its beam
    // (sine max_gap / range): beyond it the walk stops.
    const double ratio = std::min(1.0, params.max_gap / last_range);
    const double min_cos = std::sqrt(1.0 - ratio * ratio);
    double nearest_through = std::numeric_limits<double>::infinity();
    for (std::ptrdiff_t j = position; j < n; ++j) {
      const std::size_t k = beamAt(j);
      if (!usable[k]) continue;  // nothing usable: part of the gap
      const double range = (points[k] - origin).norm();
      if (to_last.dot(points[k] - origin) < min_cos * last_range * range) return -1;
      if (j > position && (points[k] - run.back()).squaredNorm() <= gap_sq)
        return nearest_through > range + params.end_step && continuesRun(run, points[k], params) &&
                       surface_across_gap(run.back(), points[k])
                   ? j
                   : -1;
      // Not the surface again: the beam must have seen through it.
      if (!(range > last_range + params.end_step)) return -1;
      nearest_through = std::min(nearest_through, range);
    }
    return -1;
  };
  for (std::ptrdiff_t position = 0; position < n; ++position) {
    std::size_t i = beamAt(position);
    bool joins = usable[i] && (run.empty() || (points[i] - run.back()).squaredNorm() <= spacing_sq);
    if (!joins && !run.empty()) {
      const std::ptrdiff_t across = acrossGap(position);
      if (across >= 0) position = across, i = beamAt(position), joins = true;
    }
    if (!joins && !run.empty()) finishRun(position);
    if (!usable[i]) continue;
    if (run.empty()) first = position;
    run.push_back(points[i]);
  }
  if (!run.empty()) finishRun(n);
  return out;
}

}  // namespace scanfilter
