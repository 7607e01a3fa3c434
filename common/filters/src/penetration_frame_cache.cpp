// PenetrationFilter, part 2 of 4: the frame cache. Frames come in (their
// votes into the grid), age out after T_max or when the cache is full, are
// dropped all at once when the sensor jumps, and join the rescue's evidence
// once the sensor has moved rescue_min_baseline away from where they were
// taken. penetration_filter.cpp has the frame's way through the filter.
#include <algorithm>
#include <cmath>
#include <utility>

#include <spdlog/spdlog.h>

#include "return_masks.hpp"
#include "scanfilter/depth_edges.hpp"
#include "scanfilter/grazing_returns.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

void PenetrationFilter::reset() {
  cache_.clear();
  grid_.clear();
  evidence_.clear();
  kept_from_afar_.clear();
  memory_.clear();
  frames_seen_ = 0;
  last_origin_.reset();
  correction_ = Eigen::Isometry2d::Identity();
}

void PenetrationFilter::resetOnPoseJump(const Eigen::Vector2d& origin, Stamp stamp) {
  if (last_origin_ && (origin - *last_origin_).norm() > params_.pose_jump_reset) {
    // A relocalisation or a bad pose: the cached frames no longer line up
    // with the new one, so judging against them would delete good points.
    spdlog::info("penetration filter: sensor moved {:.3f} m between frames at stamp {} "
                 "(limit {:.3f} m); cache reset",
                 (origin - *last_origin_).norm(), stamp.toDecimal(), params_.pose_jump_reset);
    reset();
    ++resets_;
  }
  last_origin_ = origin;
}

void PenetrationFilter::dropOldestFrame() {
  const CachedFrame& oldest = cache_.front();
  grid_.remove(oldest.votes);
  if (oldest.in_evidence) removeRescueEvidence(oldest);
  cache_.pop_front();
}

void PenetrationFilter::expireFrames(Stamp stamp) {
  while (!cache_.empty() && stamp.secondsSince(cache_.front().stamp) > params_.frame_lifetime) dropOldestFrame();
}

void PenetrationFilter::makeRoomForAFrame() {
  while (!cache_.empty() && cache_.size() >= params_.max_cache_frames) dropOldestFrame();
}

bool PenetrationFilter::cachesFrameAt(Stamp stamp) const {
  if (cache_.empty()) return true;
  const double since = stamp.secondsSince(cache_.back().stamp);
  // A stamp that did not advance says nothing about time (csail's log has
  // two distinct stamps for 406 scans): every such frame is cached, as before.
  return since <= 0.0 || since >= params_.cache_min_interval;
}

void PenetrationFilter::cacheFrame(const Scan& scan, const SensorInfo& sensor, const Eigen::Vector2d& origin,
                                   std::span<const std::uint8_t> labels) {
  // Without a baseline the frame's returns are evidence at once, added here
  // (its votes' runs, then the others'); with one, admitEvidence adds them later.
  const bool evidence_now = params_.rescue_persistent_points && !evidenceWaitsForBaseline();
  CachedFrame frame{scan.stamp, origin, {}, {}, evidence_now, std::nullopt};
  // Only with the switch on: every frame goes through here.
  const int edge_beams = edgeHalfWidthBeams(scan);
  const BeamMask edge =
      edge_beams > 0 ? nearSideOfDepthEdge(scan, keptReturns(labels), edge_beams, params_.edge_depth_step)
                     : BeamMask{};
  frame.placed_origin = correction_ * origin;
  const BeamMask grazing =
      params_.grazing_vote_max_deg > 0.0
          ? returnsAtGrazingIncidence(points_, frame.placed_origin, scan.angle_increment,
                                      params_.grazing_vote_max_deg, params_.straddle_half_width)
          : BeamMask{};
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const auto code = static_cast<PointCode>(labels[i]);
    if (code == PointCode::kNoReturn) continue;
    // At a depth edge or at grazing incidence a return lands off its surface.
    const bool off_its_surface = (!edge.empty() && edge[i]) || (!grazing.empty() && grazing[i]);
    // The mask is the free-space check's: it holds only while the return is
    // still the jump point that check made it.
    const bool lone_seen_through =
        code == PointCode::kJump && !lone_seen_through_.empty() && lone_seen_through_[i];
    const bool votes = !off_its_surface && (code == PointCode::kValid || lone_seen_through ||
                                    (code == PointCode::kMisdetected && params_.cache_misdetected_points));
    if (votes) grid_.appendToRuns(frame.votes, points_[i]);
    else if (params_.rescue_persistent_points) grid_.appendToRuns(frame.others, points_[i]);
  }
  grid_.add(frame.votes);
  if (evidence_now) addRescueEvidence(frame);
  if (params_.free_space_check) frame.image.emplace(scan, sensor, correction_, labels);
  cache_.push_back(std::move(frame));
}

void PenetrationFilter::admitEvidence(const Eigen::Vector2d& origin) {
  const double baseline_sq = params_.rescue_min_baseline * params_.rescue_min_baseline;
  const auto far = [&](const CachedFrame& frame) { return (frame.origin - origin).squaredNorm() >= baseline_sq; };
  // No parallax in the whole cache: nothing to tell a leg from a mixed return by.
  const bool any_far = std::any_of(cache_.begin(), cache_.end(), far);
  for (auto& frame : cache_) {
    if (frame.in_evidence || (any_far && !far(frame))) continue;
    addRescueEvidence(frame);
    frame.in_evidence = true;
  }
}

void PenetrationFilter::addRescueEvidence(const CachedFrame& frame) {
  evidence_.add(frame.votes);
  evidence_.add(frame.others);
  if (countsKeptReturnsFromAfar()) kept_from_afar_.add(frame.votes);
}

void PenetrationFilter::removeRescueEvidence(const CachedFrame& frame) {
  evidence_.remove(frame.votes);
  evidence_.remove(frame.others);
  if (countsKeptReturnsFromAfar()) kept_from_afar_.remove(frame.votes);
}

int PenetrationFilter::edgeHalfWidthBeams(const Scan& scan) const {
  if (params_.edge_vote_margin_deg <= 0.0 || !(std::abs(scan.angle_increment) > 0.0)) return 0;
  return static_cast<int>(beamsSpanning(params_.edge_vote_margin_deg, scan.angle_increment, scan.size()));
}

}  // namespace scanfilter
