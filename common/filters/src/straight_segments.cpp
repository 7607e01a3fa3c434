#include "scanfilter/straight_segments.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

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

// One walk along a frame's beams, from a break (on a full turn) or from the
// first beam, cutting the usable returns into runs and the runs into
// segments. Positions count beams from where the walk starts.
class RunWalk {
 public:
  RunWalk(std::span<const Eigen::Vector2d> points, const BeamMask& usable, const Eigen::Vector2d& origin,
          const StraightSegmentParams& params, bool full_turn, const SurfaceAcrossGap& surface_across_gap)
      : points_(points),
        usable_(usable),
        origin_(origin),
        params_(params),
        full_turn_(full_turn),
        surface_across_gap_(params.max_gap > 0.0 ? surface_across_gap : SurfaceAcrossGap{}),
        n_(static_cast<std::ptrdiff_t>(points.size())),
        spacing_sq_(params.max_spacing * params.max_spacing),
        start_(full_turn ? static_cast<std::ptrdiff_t>(firstBeamAfterABreak(points, usable, spacing_sq_)) : 0) {}

  std::vector<StraightSegment> segments();

 private:
  std::size_t beamAt(std::ptrdiff_t position) const { return static_cast<std::size_t>((start_ + position) % n_); }
  double rangeAt(std::size_t beam) const { return (points_[beam] - origin_).norm(); }
  bool joinsRun(std::size_t beam) const {
    return usable_[beam] && (run_.empty() || (points_[beam] - run_.back()).squaredNorm() <= spacing_sq_);
  }
  bool seenPast(std::ptrdiff_t position, const Eigen::Vector2d& end) const;
  void finishRun(std::ptrdiff_t end);
  std::optional<std::ptrdiff_t> returnAcrossGap(std::ptrdiff_t position) const;
  bool continuesRun(const Eigen::Vector2d& p) const;

  std::span<const Eigen::Vector2d> points_;
  const BeamMask& usable_;
  Eigen::Vector2d origin_;
  const StraightSegmentParams& params_;
  bool full_turn_;
  SurfaceAcrossGap surface_across_gap_;  // empty: runs never cross a gap
  std::ptrdiff_t n_;
  double spacing_sq_;
  std::ptrdiff_t start_;
  std::vector<Eigen::Vector2d> run_;
  std::ptrdiff_t first_ = 0;  // the run's first position
  // On a full turn with gaps to cross, the walk's first run waits for its
  // last: a run that ends the walk may go on across a gap into it.
  std::vector<Eigen::Vector2d> opening_run_;
  std::ptrdiff_t opening_first_ = -1, opening_end_ = -1;
  std::vector<StraightSegment> out_;
};

bool RunWalk::seenPast(std::ptrdiff_t position, const Eigen::Vector2d& end) const {
  if (!full_turn_ && (position < 0 || position >= n_)) return false;  // a partial scan starts at 0
  const std::size_t j = beamAt(((position % n_) + n_) % n_);
  return usable_[j] && rangeAt(j) > (end - origin_).norm() + params_.end_step;
}

void RunWalk::finishRun(std::ptrdiff_t end) {  // the run is positions [first_, end)
  const std::size_t before = out_.size();
  splitAndFit(run_, run_, params_, out_);
  for (std::size_t k = before; k < out_.size(); ++k) {
    out_[k].a_seen_past = out_[k].a_seen_past && seenPast(first_ - 1, run_.front());
    out_[k].b_seen_past = out_[k].b_seen_past && seenPast(end, run_.back());
  }
  run_.clear();
}

// Whether p lies on the line of the run's last returns (min_returns of
// them, or all), within max_deviation, and on beyond its last return: the
// same surface across a gap, not a step to another one. Those returns must
// span half the gap at least: a direction taken over a span L, off by
// about range noise / L, moves the line at p by that times the gap.
bool RunWalk::continuesRun(const Eigen::Vector2d& p) const {
  if (run_.size() < 2) return false;
  const std::size_t tail = std::min(run_.size(), static_cast<std::size_t>(std::max(2, params_.min_returns)));
  const Eigen::Vector2d& from = run_[run_.size() - tail];
  const Eigen::Vector2d& last = run_.back();
  const bool long_enough = (last - from).norm() >= 0.5 * (p - last).norm();
  return long_enough && distanceToLine(p, from, last) <= params_.max_deviation && (p - last).dot(last - from) > 0.0;
}

// The position of the return that continues the run across a gap that
// starts at `position` (the first beam that does not join), if any: past
// beams that saw through (farther than the returns either side by
// end_step) or gave nothing usable, the first usable return within max_gap
// of the run's last, on its line, where surface_across_gap vouches for a
// surface between the two. On a full turn the walk may go on past its end
// into the first run.
std::optional<std::ptrdiff_t> RunWalk::returnAcrossGap(std::ptrdiff_t position) const {
  if (!surface_across_gap_) return std::nullopt;
  const Eigen::Vector2d to_last = run_.back() - origin_;
  const double last_range = to_last.norm();
  // A return within max_gap of the last lies within this angle of its beam
  // (sine max_gap / range): beyond it the walk stops.
  const double ratio = std::min(1.0, params_.max_gap / last_range);
  const double min_cos = std::sqrt(1.0 - ratio * ratio);
  const std::ptrdiff_t limit = opening_first_ >= 0 ? n_ + opening_first_ + 1 : n_;
  double nearest_through = std::numeric_limits<double>::infinity();
  for (std::ptrdiff_t j = position; j < limit; ++j) {
    const std::size_t k = beamAt(j);
    if (!usable_[k]) continue;  // nothing usable: part of the gap
    const double range = rangeAt(k);
    if (to_last.dot(points_[k] - origin_) < min_cos * last_range * range) return std::nullopt;
    if (j > position && (points_[k] - run_.back()).squaredNorm() <= params_.max_gap * params_.max_gap) {
      const bool across = nearest_through > range + params_.end_step && continuesRun(points_[k]) &&
                          surface_across_gap_(run_.back(), points_[k]);
      return across ? std::optional<std::ptrdiff_t>(j) : std::nullopt;
    }
    if (!(range > last_range + params_.end_step)) return std::nullopt;  // not seen through: in front, or aside
    nearest_through = std::min(nearest_through, range);
  }
  return std::nullopt;
}

std::vector<StraightSegment> RunWalk::segments() {
  const bool opening_waits = full_turn_ && surface_across_gap_;
  for (std::ptrdiff_t position = 0; position < n_; ++position) {
    std::size_t i = beamAt(position);
    bool joins = joinsRun(i);
    if (!joins && !run_.empty()) {
      if (const auto across = returnAcrossGap(position)) {
        if (*across >= n_) {  // into the first run: one run across the walk's end
          run_.insert(run_.end(), opening_run_.begin(), opening_run_.end());
          opening_run_.clear();
          finishRun(opening_end_ + n_);
          opening_first_ = -1;
          return std::move(out_);
        }
        position = *across;
        i = beamAt(position);
        joins = true;
      }
    }
    if (!joins && !run_.empty()) {
      if (opening_waits && opening_first_ < 0) {
        opening_run_.swap(run_);
        opening_first_ = first_;
        opening_end_ = position;
      } else {
        finishRun(position);
      }
    }
    if (!usable_[i]) continue;
    if (run_.empty()) first_ = position;
    run_.push_back(points_[i]);
  }
  if (!run_.empty()) finishRun(n_);
  if (opening_first_ >= 0) {  // the first run, on its own
    run_.swap(opening_run_);
    first_ = opening_first_;
    finishRun(opening_end_);
  }
  return std::move(out_);
}

}  // namespace

std::vector<StraightSegment> straightSegments(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                                              const Eigen::Vector2d& origin, const StraightSegmentParams& params,
                                              bool full_turn, const SurfaceAcrossGap& surface_across_gap) {
  return RunWalk(points, usable, origin, params, full_turn, surface_across_gap).segments();
}

}  // namespace scanfilter
