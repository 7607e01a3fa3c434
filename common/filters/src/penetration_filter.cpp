// PenetrationFilter, part 1 of 4: a frame's way through step 2 (placed,
// aligned to the cache, judged, remembered, cached) and the paper's
// penetration model, in a reference and a fast implementation. The other
// parts: penetration_frame_cache.cpp (the cache), penetration_sparse_surfaces.cpp
// (lines of single returns) and penetration_checks.cpp (the checks beyond the
// paper that follow the model).
#include "scanfilter/penetration_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "return_masks.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

PenetrationFilter::PenetrationFilter(const PenetrationFilterParams& params)
    : params_(params),
      rule_(params),
      evidence_along_beam_(rule_, params.surface_gap, surfaceGoesOnTest(params)),
      grid_(params.cell_size, params.obstacle_threshold),
      evidence_(params.cell_size),  // the same cells as grid_: a frame's runs go into both
      kept_from_afar_(params.cell_size),
      aligner_(params.alignment),
      free_space_(params),
      thin_objects_(params.thin_object_depth_step, params.thin_object_radius),
      memory_(params.surface_memory),
      mirror_ghosts_(params.surface_memory.mirror_ghosts),
      // Every count it sizes is the rescue's evidence: without the rescue
      // nothing asks. The noise it measures also widens the sparse-surface
      // search's limits (42), which needs it with or without the rescue.
      evidence_radius_({.min_radius = params.rescue_radius,
                        .noise_sigmas = params.rescue_persistent_points ? params.evidence_noise_sigmas : 0.0,
                        .max_radius = params.evidence_radius_max,
                        .sampling = params.evidence_noise_sampling,
                        .measure_noise = followsRangeNoise(params.surface_memory.sparse_surfaces)}) {}

void PenetrationFilter::apply(const Scan& scan, const SensorInfo& sensor,
                              std::span<std::uint8_t> labels) {
  // Labels come from upstream (a message, a log): a beam without a return is
  // no return whatever they say, or its NaN point would enter the grid.
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (!scan.hasReturn(i)) labels[i] = static_cast<std::uint8_t>(PointCode::kNoReturn);
  const Eigen::Vector2d origin = sensorOrigin(scan.pose, sensor.mount);
  resetOnPoseJump(origin, scan.stamp);
  evidence_radius_.measure(scan, sensor);
  ++frames_seen_;
  expireFrames(scan.stamp);
  // Where the last correction puts the sensor: within the alignment's step.
  if (memory_.enabled()) memory_.forget(correction_ * origin, scan.stamp);
  // Decided before judging, so that a frame the cache will skip does not
  // push the oldest one out (and is judged against all of them).
  const bool caches = cachesFrameAt(scan.stamp);
  if (caches) makeRoomForAFrame();
  if (evidenceWaitsForBaseline()) admitEvidence(origin);
  lone_seen_through_.clear();  // a frame not judged (or not checked) marked none
  if (warmedUp()) {
    const Judgement judgement = alignAndJudge(scan, sensor, labels);
    correction_ = judgement.correction;
    unaligned_ += !judgement.judged;
    // After judging, so that a frame's own surfaces never judge it.
    if (judgement.judged && memory_.enabled()) {
      const BeamMask returns = allReturns(scan);
      memory_.forgetSeenThroughHeadOn(points_, returns, judgement.origin);
      // A gap in a surface the frame sees through is bridged where the cache
      // (other frames) holds that surface: a pane's holes, not an opening.
      const SurfaceAcrossGap cache_holds = [this](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return grid_.holdsSurfaceBetween(a, b);
      };
      const bool remembered =
          memory_.remember(points_, keptReturns(labels), judgement.origin, scan.stamp, isFullTurn(scan), cache_holds);
      if (remembered && params_.surface_memory.sparse_surfaces.enabled)
        rememberSparseSurfaces(judgement.origin, scan.stamp);
      memory_.confirmPanesAndMirrors(points_, returns, judgement.origin);
    }
  } else {
    placeFrame(scan, sensor);
  }
  // Where the alignment put it: the cache stays self-consistent.
  if (caches) cacheFrame(scan, sensor, origin, labels);
}

void PenetrationFilter::judge(const Scan& scan, const SensorInfo& sensor,
                              std::span<std::uint8_t> labels) {
  alignAndJudge(scan, sensor, labels);
}

Eigen::Vector2d PenetrationFilter::placeFrame(const Scan& scan, const SensorInfo& sensor) {
  worldPoints(scan, sensor, directions_, points_);
  if (correction_.matrix() == Eigen::Matrix3d::Identity()) return sensorOrigin(scan.pose, sensor.mount);
  for (auto& p : points_) p = correction_ * p;  // NaN stays NaN
  return correction_ * sensorOrigin(scan.pose, sensor.mount);
}

PenetrationFilter::Judgement PenetrationFilter::alignAndJudge(const Scan& scan, const SensorInfo& sensor,
                                                              std::span<std::uint8_t> labels) {
  Eigen::Vector2d origin = placeFrame(scan, sensor);
  Judgement out{false, correction_};
  if (params_.alignment.enabled) {
    const FrameAlignment fit = aligner_.align(grid_, points_, keptReturns(labels), origin);
    if (!fit.good) return out;  // judged against a cache it does not fit, good points would go
    for (auto& p : points_) p = fit.correction * p;
    origin = fit.correction * origin;
    out.correction = fit.correction * correction_;
  }
  findSurfaceEnds(scan);
  judgePoints(origin, labels);
  if (params_.free_space_check) markSeenThrough(scan, origin, labels);
  if (params_.thin_object_check) markMixedReturnsOfThinObjects(scan, origin, sensor.range_max, labels);
  if (memory_.enabled()) markBeyondRememberedSurfaces(scan.stamp, origin, labels);
  out.judged = true;
  out.origin = origin;
  return out;
}

void PenetrationFilter::findSurfaceEnds(const Scan& scan) {
  surface_ends_.clear();
  if (params_.edge_smear_radius > 0.0) {
    for (std::size_t i = 0; i < scan.size(); ++i) {
      // NaN (no return) compares false either side: it is no neighbour
      // beyond, and a beam without a return ends nothing.
      const double beyond = scan.ranges[i] + params_.edge_depth_step;
      const bool before = i > 0 && scan.ranges[i - 1] > beyond;
      const bool after = i + 1 < scan.size() && scan.ranges[i + 1] > beyond;
      // Farther returns on both sides: no end of anything the frame sees
      // (a pane or a mirror seen in one beam, a leg).
      if (before == after) continue;
      const std::optional<Eigen::Vector2d> inside = surfaceBehind(scan, i, before ? 1 : -1);
      if (inside && cacheEndsToo(points_[i], *inside)) surface_ends_.push_back(points_[i]);
    }
  }
  smear_zone_.build(surface_ends_, params_.edge_smear_radius);
}

std::optional<Eigen::Vector2d> PenetrationFilter::surfaceBehind(const Scan& scan, std::size_t i,
                                                                std::ptrdiff_t step) const {
  const double reach_sq = params_.edge_smear_radius * params_.edge_smear_radius;
  const double gap_sq = params_.edge_depth_step * params_.edge_depth_step;
  const auto n = static_cast<std::ptrdiff_t>(scan.size());
  for (auto j = static_cast<std::ptrdiff_t>(i) + step, k = static_cast<std::ptrdiff_t>(i); j >= 0 && j < n;
       k = j, j += step) {
    if (!scan.hasReturn(static_cast<std::size_t>(j))) return std::nullopt;
    const Eigen::Vector2d& pj = points_[static_cast<std::size_t>(j)];
    if ((pj - points_[static_cast<std::size_t>(k)]).squaredNorm() > gap_sq) return std::nullopt;
    if ((pj - points_[i]).squaredNorm() >= reach_sq) return pj;
  }
  return std::nullopt;
}

bool PenetrationFilter::cacheEndsToo(const Eigen::Vector2d& end, const Eigen::Vector2d& inside) const {
  // A pane or a mirror the frame sees only in places also "ends" where the
  // frame stops seeing it, but the cache holds it on beyond: look along the
  // surface past the fringe's reach for any obstacle cell: the probe's cell
  // and its 8 neighbours, the probe two cells past the reach, so that the
  // block comes no nearer the end than the reach.
  constexpr double kProbeCellsPastReach = 2.0;
  const Eigen::Vector2d outward = (end - inside).normalized();
  const CellIndex c =
      grid_.cellOf(end + outward * (params_.edge_smear_radius + kProbeCellsPastReach * grid_.cellSize()));
  return !grid_.anyObstacleIn({c.x - 1, c.y - 1}, {c.x + 1, c.y + 1});
}

void PenetrationFilter::judgePoints(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels) {
  if (params_.rescue_persistent_points) rescuePersistentPoints(origin, labels);
  prepareJudging(origin);
  markMisdetected(origin, labels);
}

double PenetrationFilter::ownMarginSq(const Eigen::Vector2d& origin, std::size_t i, double length) const {
  double margin = rule_.ownMargin(length);
  if (params_.grazing_margin)
    margin = std::max(margin, std::min(grazingRun(origin, i), params_.grazing_margin_max));
  return margin * margin;
}

PenetrationEvidence::SurfaceGoesOn PenetrationFilter::surfaceGoesOnTest(const PenetrationFilterParams& params) {
  if (!params.require_surface_extent) return {};
  return [this](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return obstaclePastAlongLine(a, b) || obstaclePastAlongLine(b, a);
  };
}

bool PenetrationFilter::obstaclePastAlongLine(const Eigen::Vector2d& from, const Eigen::Vector2d& to) const {
  // The next cell of a surface along the line from `from` through `to`: its
  // obstacle position (a centroid anywhere in its cell) half a cell to a
  // cell and a half past `to`, within half a cell of the line. Such a
  // position lies within the cells around the point a cell past `to`.
  constexpr double kNearestCells = 0.5, kFarthestCells = 1.5, kOffLineCells = 0.5;
  const double cell = grid_.cellSize();
  const Eigen::Vector2d along_line = (to - from).normalized();
  const CellIndex next = grid_.cellOf(to + along_line * cell);
  return grid_.anyObstacleIn({next.x - 1, next.y - 1}, {next.x + 1, next.y + 1}, [&](CellIndex c) {
    const Eigen::Vector2d q = obstaclePosition(c);
    const Eigen::Vector2d w = q - to;
    const double past = w.dot(along_line);
    return countsAsObstacle(q) && past >= kNearestCells * cell && past <= kFarthestCells * cell &&
           std::abs(cross(along_line, w)) <= kOffLineCells * cell;
  });
}

double PenetrationFilter::grazingRun(const Eigen::Vector2d& origin, std::size_t i) const {
  // One surface only when p lies on the line through its neighbours.
  const auto surface = localSurfaceDirection(points_, i, params_.straddle_half_width);
  const Eigen::Vector2d beam = points_[i] - origin;
  if (!surface || beam.squaredNorm() == 0.0) return 0.0;
  // straddle / tan(grazing angle): |beam · surface| / |beam × surface|.
  const double across = std::abs(beam.x() * surface->y() - beam.y() * surface->x());
  const double along = std::abs(beam.dot(*surface));
  if (across == 0.0) return std::numeric_limits<double>::infinity();  // the beam runs along it
  return params_.straddle_half_width * along / across;
}

// --- Reference ---------------------------------------------------------------

void ReferencePenetrationFilter::prepareJudging(const Eigen::Vector2d& /*origin*/) {
  // Step 6: cells counting more than obs_th points are the obstacle set Q.
  obstacles_.clear();
  grid_.forEachCellAbove(params_.obstacle_threshold,
                         [this](CellIndex c, int) {
                           const Eigen::Vector2d q = obstaclePosition(c);
                           if (countsAsObstacle(q)) obstacles_.push_back(q);
                         });
}

void ReferencePenetrationFilter::markMisdetected(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels) {
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != static_cast<std::uint8_t>(PointCode::kValid)) continue;
    if (isMisdetected(origin, points_[i], ownMarginSq(origin, i)))
      labels[i] = static_cast<std::uint8_t>(PointCode::kMisdetected);
  }
}

bool ReferencePenetrationFilter::isMisdetected(const Eigen::Vector2d& r, const Eigen::Vector2d& p,
                                               double own_sq) {
  evidence_along_beam_.reset();
  for (const auto& q : obstacles_)  // steps a-f: every obstacle cell in turn
    if (evidence_along_beam_.add(rule_.evidence(r, p, q, own_sq), q)) return true;
  return false;
}

// --- Fast ----------------------------------------------------------------------

void FastPenetrationFilter::prepareJudging(const Eigen::Vector2d& origin) {
  // The reach of this frame: its points and the sensor, widened by how far
  // off a beam and beyond its point a penetrating cell can lie.
  Eigen::AlignedBox2d box = returnBounds(points_);
  box.extend(origin);
  const double reach = rule_.outerHalfWidth() + positionSlack() + rule_.behindMargin() + grid_.cellSize();
  window_.build(grid_, grid_.cellOf(box.min().array() - reach), grid_.cellOf(box.max().array() + reach),
                [this](CellIndex c) { return obstaclePosition(c); });
  eraseEdgeFringes();
}

void FastPenetrationFilter::eraseEdgeFringes() {
  // Only the cells around the ends are asked (a frame has few ends, each
  // reaching a few cells), with the reference's own test.
  const double reach = params_.edge_smear_radius + positionSlack();
  for (const Eigen::Vector2d& end : surfaceEnds()) {
    grid_.forEachObstacleIn(grid_.cellOf(end.array() - reach), grid_.cellOf(end.array() + reach), [&](CellIndex c) {
      if (!countsAsObstacle(obstaclePosition(c))) window_.erase(c);
    });
  }
}

std::optional<FastPenetrationFilter::Beam> FastPenetrationFilter::beamOf(const Eigen::Vector2d& origin,
                                                                        std::size_t i) const {
  const Eigen::Vector2d v = points_[i] - origin;
  const double length = v.norm();
  if (!std::isfinite(length) || length <= 0.0) return std::nullopt;
  const double own_sq = ownMarginSq(origin, i, length);
  // Penetrating cells project onto the beam between the sensor and the
  // reach; the slack keeps the walk a superset whatever the rounding.
  double reach = rule_.reachAlongBeam(length, own_sq) + detail::kBoundSlack;
  if (reach <= 0.0) return std::nullopt;
  // At least a cell: the walk's slope comes from its end minus the origin,
  // which must not be a vector of rounding errors (walking farther only adds
  // cells to test).
  reach = std::max(reach, grid_.cellSize());
  return Beam{i, own_sq, BundledBeam{v / length, reach}};
}

void FastPenetrationFilter::markMisdetected(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels) {
  bundle_.clear();
  bundle_walks_.clear();
  double max_reach = 0.0;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != static_cast<std::uint8_t>(PointCode::kValid)) continue;
    const std::optional<Beam> beam = beamOf(origin, i);
    if (!beam) continue;
    const bool fits = !bundle_.empty() && bundle_.size() < kMaxBundleBeams &&
                      fanSpread(bundle_walks_.front(), beam->walk, std::max(max_reach, beam->walk.reach)) <=
                          maxExtraBundleWidth();
    if (!fits) {  // judge the bundle so far, start the next with this beam
      judgeBundle(origin, labels);
      max_reach = 0.0;
    }
    max_reach = std::max(max_reach, beam->walk.reach);
    bundle_walks_.push_back(beam->walk);
    bundle_.push_back(*beam);
  }
  judgeBundle(origin, labels);
}

void FastPenetrationFilter::judgeBundle(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels) {
  if (bundle_.empty()) return;
  // Exact, whatever order the beams came in; only a bundle fanning out past
  // 120° has none, and then each beam walks alone.
  const std::optional<BundleBand> band =
      bundle_.size() > 1 ? bundleBand(bundle_walks_, walkHalfWidth()) : std::nullopt;
  if (!band) {
    for (const Beam& beam : bundle_)
      if (walkAlone(origin, beam)) labels[beam.index] = static_cast<std::uint8_t>(PointCode::kMisdetected);
  } else {
    bundle_cells_.clear();
    bundle_offsets_.clear();
    window_.anyAlongRay(origin, origin + band->axis * band->length, band->half_width,
                        [this, &origin](CellIndex, const Eigen::Vector2d& q) {
                          bundle_cells_.push_back(q);
                          bundle_offsets_.push_back(q - origin);
                          return false;
                        });
    for (const Beam& beam : bundle_)
      if (isMisdetected(origin, beam))
        labels[beam.index] = static_cast<std::uint8_t>(PointCode::kMisdetected);
  }
  bundle_.clear();
  bundle_walks_.clear();
}

bool FastPenetrationFilter::walkAlone(const Eigen::Vector2d& origin, const Beam& beam) {
  // Stops at the first conclusive cell.
  evidence_along_beam_.reset();
  const Eigen::Vector2d end = origin + beam.walk.unit * beam.walk.reach;
  return window_.anyAlongRay(origin, end, walkHalfWidth(),
                             [&](CellIndex, const Eigen::Vector2d& q) { return addBeamEvidence(origin, beam, q); });
}

std::size_t FastPenetrationFilter::keepCellsNearBeam(const Eigen::Vector2d& origin, const Beam& beam) {
  // The rule's test (c) on the offsets the bundle took once, without a
  // branch: every index is written, the count moves on only for those kept.
  const Eigen::Vector2d v = points_[beam.index] - origin;
  const double limit = rule_.nearBeamLimit(v);
  near_cell_indices_.resize(bundle_offsets_.size());
  std::size_t near = 0;
  for (std::size_t k = 0; k < bundle_offsets_.size(); ++k) {
    near_cell_indices_[near] = static_cast<std::uint32_t>(k);
    near += PenetrationRule::nearBeam(v, bundle_offsets_[k], limit);
  }
  return near;
}

bool FastPenetrationFilter::isMisdetected(const Eigen::Vector2d& origin, const Beam& beam) {
  // Most of a bundle's cells lie beside this beam, off it by more than the
  // rule's outer half width: they say nothing (kNone), so only the others
  // meet the whole rule. The evidence does not depend on the order of the
  // cells, so testing them in walk order gives the beam's own walk's answer.
  const std::size_t near = keepCellsNearBeam(origin, beam);
  evidence_along_beam_.reset();
  for (std::size_t k = 0; k < near; ++k)
    if (addBeamEvidence(origin, beam, bundle_cells_[near_cell_indices_[k]])) return true;
  return false;
}

bool FastPenetrationFilter::addBeamEvidence(const Eigen::Vector2d& origin, const Beam& beam, const Eigen::Vector2d& q) {
  return evidence_along_beam_.add(rule_.evidence(origin, points_[beam.index], q, beam.own_sq), q);
}

std::unique_ptr<PenetrationFilter> makePenetrationFilter(const PenetrationFilterParams& params,
                                                         Implementation impl) {
  if (impl == Implementation::kReference)
    return std::make_unique<ReferencePenetrationFilter>(params);
  return std::make_unique<FastPenetrationFilter>(params);
}

}  // namespace scanfilter
