#include "scanfilter/penetration_filter.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <limits>
#include <unordered_map>

#include <spdlog/spdlog.h>

#include "scanfilter/cell_key.hpp"
#include "scanfilter/depth_edges.hpp"
#include "scanfilter/grazing_returns.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sparse_surfaces.hpp"

namespace scanfilter {

namespace {
// The returns this frame keeps so far: the ones that pull the alignment's fit
// (step 1's jump points lie on no surface), and the far side of a depth edge
// that counts (ghosts behind a mirror or a pane that this frame has marked
// do not silence the pane's own returns next to them).
BeamMask keptReturns(std::span<const std::uint8_t> labels) {
  BeamMask kept(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) kept.set(i, labels[i] == static_cast<std::uint8_t>(PointCode::kValid));
  return kept;
}

// Every return, kept or not (the free-space check's far side of an edge).
BeamMask allReturns(const Scan& scan) {
  BeamMask returns(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) returns.set(i, scan.hasReturn(i));
  return returns;
}
}  // namespace

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
      // nothing asks, and the noise is not measured.
      evidence_radius_({.min_radius = params.rescue_radius,
                        .noise_sigmas = params.rescue_persistent_points ? params.evidence_noise_sigmas : 0.0,
                        .max_radius = params.evidence_radius_max,
                        .sampling = params.evidence_noise_sampling}) {}

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
      memory_.forgetSeenThroughHeadOn(points_, allReturns(scan), judgement.origin);
      // A gap in a surface the frame sees through is bridged where the cache
      // (other frames) holds that surface: a pane's holes, not an opening.
      const SurfaceAcrossGap cache_holds = [this](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return grid_.holdsSurfaceBetween(a, b);
      };
      const bool remembered =
          memory_.remember(points_, keptReturns(labels), judgement.origin, scan.stamp, isFullTurn(scan), cache_holds);
      if (remembered && params_.surface_memory.sparse_surfaces.enabled)
        rememberSparseSurfaces(judgement.origin, scan.stamp);
      memory_.confirmPanesAndMirrors(points_, allReturns(scan), judgement.origin);
    }
  } else {
    placeFrame(scan, sensor);
  }
  // Where the alignment put it: the cache stays self-consistent.
  if (caches) cacheFrame(scan, sensor, origin, labels);
}

void PenetrationFilter::rememberSparseSurfaces(const Eigen::Vector2d& origin, Stamp stamp) {
  const SparseSurfaceParams& sparse = params_.surface_memory.sparse_surfaces;
  std::vector<CellMean> cells = cellsInReach(origin);
  std::vector<StraightSegment> found = sparseSurfaces(cells, grid_.cellSize(), sparse);
  if (found.empty()) return;
  // A return seen beyond a surface is no evidence of another: a mirror's or
  // a pane's reflections line up too, as the image of the wall they came
  // from. So the surfaces found, at any angle, are remembered in a copy of
  // the memory, which then serves to find the cells on them that a cached
  // frame saw beyond a surface; the search runs again without those (what
  // it then finds is not asked again).
  SurfaceMemory surfaces = memory_;
  surfaces.rememberSegments(found, origin, stamp, 0.0);
  if (dropCellsSeenBeyond(surfaces, found, stamp, cells)) found = sparseSurfaces(cells, grid_.cellSize(), sparse);
  memory_.rememberSegments(found, origin, stamp, sparse.min_beam_surface_angle_deg);
}

std::vector<CellMean> PenetrationFilter::cellsInReach(const Eigen::Vector2d& origin) const {
  Eigen::AlignedBox2d box = returnBounds(points_);
  box.extend(origin);
  std::vector<CellMean> cells;
  grid_.forEachCountedCellIn(grid_.cellOf(box.min()), grid_.cellOf(box.max()),
                             [&](CellIndex c, int count, const Eigen::Vector2d& at) {
                               cells.push_back({c, at, count <= params_.obstacle_threshold});
                             });
  return cells;
}

bool PenetrationFilter::dropCellsSeenBeyond(const SurfaceMemory& surfaces, std::span<const StraightSegment> found,
                                            Stamp stamp, std::vector<CellMean>& cells) const {
  // Only the sparse cells on the surfaces found are asked: the others could
  // change what is found only as neighbours, and asking every cached run
  // about every sparse cell cost as much as the search itself.
  const double tolerance = params_.surface_memory.sparse_surfaces.max_deviation + grid_.cellSize();
  const auto onAFoundSurface = [&](const Eigen::Vector2d& p) {
    return std::any_of(found.begin(), found.end(), [&](const StraightSegment& s) {
      return distanceToSegment(p, s.a, s.b) <= tolerance;
    });
  };
  std::unordered_map<std::uint64_t, std::size_t> asked;  // cell key -> index in `cells`
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (cells[i].sparse && onAFoundSurface(cells[i].at)) asked.emplace(cellKey(cells[i].cell.x, cells[i].cell.y), i);
  std::vector<bool> seen_beyond(cells.size(), false);
  bool any = false;
  for (const CachedFrame& frame : cache_) {
    for (const CellRun& run : frame.votes) {
      const auto it = asked.find(cellKey(run.cell.x, run.cell.y));
      if (it == asked.end() || seen_beyond[it->second]) continue;
      seen_beyond[it->second] = surfaces.liesBeyondASurface(frame.placed_origin, cells[it->second].at, stamp);
      any = any || seen_beyond[it->second];
    }
  }
  if (!any) return false;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (!seen_beyond[i]) cells[kept++] = cells[i];
  cells.resize(kept);
  return true;
}

int PenetrationFilter::edgeHalfWidthBeams(const Scan& scan) const {
  if (params_.edge_vote_margin_deg <= 0.0 || !(std::abs(scan.angle_increment) > 0.0)) return 0;
  return static_cast<int>(beamsSpanning(params_.edge_vote_margin_deg, scan.angle_increment, scan.size()));
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

int PenetrationFilter::countAround(const PenetrationGrid& grid, const Eigen::Vector2d& p,
                                   const Eigen::Vector2d& origin) const {
  const CellIndex c = grid.cellOf(p);
  const double radius = evidence_radius_.at((p - origin).norm());
  const auto reach = static_cast<int>(std::ceil(radius / grid.cellSize()));
  const double radius_sq = radius * radius;
  int sum = 0;
  grid.forEachCountedIn({c.x - reach, c.y - reach}, {c.x + reach, c.y + reach},
                        [&](int count, const Eigen::Vector2d& centroid) {
                          if ((centroid - p).squaredNorm() <= radius_sq) sum += count;
                        });
  return sum;
}

bool PenetrationFilter::thinObjectStandsAt(const Eigen::Vector2d& p, const Eigen::Vector2d& origin) const {
  if (!params_.rescue_persistent_points || evidenceAround(p, origin) < params_.rescue_min_count) return false;
  // Other frames' mixed returns of the same leg land near a mixed return
  // too, and most of them were removed in their own frames; a real object's
  // returns were kept there (docs/accuracy.md, 31).
  return !params_.thin_object_evidence_kept || keptReturnsAround(p, origin) >= params_.rescue_min_count;
}

void PenetrationFilter::rescuePersistentPoints(const Eigen::Vector2d& origin, std::span<std::uint8_t> labels) {
  // The evidence holds only earlier frames, so a point cannot vouch for itself.
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != static_cast<std::uint8_t>(PointCode::kJump)) continue;
    if (evidenceAround(points_[i], origin) >= params_.rescue_min_count && hitFromAside(points_[i], origin))
      labels[i] = static_cast<std::uint8_t>(PointCode::kValid);
  }
}

bool PenetrationFilter::hitFromAside(const Eigen::Vector2d& p, const Eigen::Vector2d& origin) const {
  if (params_.rescue_min_parallax_deg <= 0.0) return true;
  const double min_sine = std::sin(degreesToRadians(params_.rescue_min_parallax_deg));
  const Eigen::Vector2d beam = (p - origin).normalized();
  bool looked = false;
  for (const CachedFrame& frame : cache_) {
    if (!frame.image) continue;  // cached without its ranges (free_space_check off)
    const Eigen::Vector2d other = (p - frame.image->origin()).normalized();
    if (std::abs(cross(beam, other)) < min_sine) continue;  // along the beam: no parallax
    const FreeSpaceCheck::Sighting sighting = free_space_.sighting(*frame.image, p);
    if (sighting == FreeSpaceCheck::Sighting::kHit) return true;
    looked = looked || sighting == FreeSpaceCheck::Sighting::kThrough;
  }
  // Nobody looked from aside (the robot drove straight at it, or has just
  // started): the evidence alone decides, as before.
  return !looked;
}

void PenetrationFilter::markSeenThrough(const Scan& scan, const Eigen::Vector2d& origin,
                                        std::span<std::uint8_t> labels) {
  const double baseline_sq = params_.rescue_min_baseline * params_.rescue_min_baseline;
  // Candidates: returns with a neighbour farther by edge_depth_step, where
  // mixed returns are. Any return counts as that neighbour, kept or not.
  const BeamMask candidate = nearSideOfDepthEdge(scan, allReturns(scan), 1, params_.edge_depth_step);
  const bool lone_returns_vote = params_.free_space_lone_returns_vote;
  const std::vector<StandsInFront> stands =
      lone_returns_vote ? standingInFront(scan, 1, params_.edge_depth_step) : std::vector<StandsInFront>{};
  if (lone_returns_vote) lone_seen_through_.assign(scan.size(), false);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != static_cast<std::uint8_t>(PointCode::kValid) || !candidate[i]) continue;
    // A return the rescue's evidence (returns of frames from elsewhere)
    // vouches for is on a surface.
    if (params_.rescue_persistent_points && evidenceAround(points_[i], origin) >= params_.free_space_veto_count)
      continue;
    int through = 0, hits = 0;
    for (const CachedFrame& frame : cache_) {
      assert(frame.image);  // cached with the check on, as every frame is
      if ((frame.image->origin() - origin).squaredNorm() < baseline_sq) continue;  // no parallax
      const FreeSpaceCheck::Sighting s = free_space_.sighting(*frame.image, points_[i]);
      through += s == FreeSpaceCheck::Sighting::kThrough;
      hits += s == FreeSpaceCheck::Sighting::kHit;
    }
    if (!free_space_.seenThrough(through, hits)) continue;
    labels[i] = static_cast<std::uint8_t>(PointCode::kJump);
    // A thin object's mixed return has that object in its footprint in front
    // of it (the thin-object check's own test); a pane's direct return has
    // nothing there.
    if (lone_returns_vote)
      lone_seen_through_.set(i, stands[i] == StandsInFront::kOfBothSides &&
                                    !objectInFootprint(origin, points_[i], scan.angle_increment));
  }
}

void PenetrationFilter::markMixedReturnsOfThinObjects(const Scan& scan, const Eigen::Vector2d& origin,
                                                      double range_max, std::span<std::uint8_t> labels) const {
  const std::vector<StandsInFront> stands = standingInFront(
      scan, static_cast<std::size_t>(std::max(0, params_.thin_object_max_beams)), params_.thin_object_depth_step);
  const double angle_step = scan.angle_increment;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != static_cast<std::uint8_t>(PointCode::kValid) || stands[i] == StandsInFront::kNo) continue;
    const bool beside_no_return = stands[i] == StandsInFront::kBesideNoReturn;
    if (beside_no_return && !params_.thin_object_beside_no_return) continue;
    // A return that returns from elsewhere vouch for (the rescue's evidence,
    // and as many of the cache's kept returns) is an object there: the rear
    // leg of a chair, partly behind a front one.
    if (thinObjectStandsAt(points_[i], origin)) continue;
    if (!objectInFootprint(origin, points_[i], angle_step)) continue;
    // With nothing within range beside it, the rest of the footprint found
    // no background there: a mix needs a second object behind the return.
    if (beside_no_return && !obstacleBehindInFootprint(origin, points_[i], angle_step, range_max)) continue;
    labels[i] = static_cast<std::uint8_t>(PointCode::kJump);
  }
}

template <typename Pred>
bool PenetrationFilter::anyCellAlongBeam(const Eigen::Vector2d& origin, const Eigen::Vector2d& unit, double from,
                                         double to, double angle_step, CellsThatCount cells, Pred&& pred) const {
  const auto holds = [&](CellIndex c) {
    const Eigen::Vector2d q = obstaclePosition(c);
    return countsAsObstacle(q) && pred(q);
  };
  // Stretch by stretch along the beam, each boxed with the footprint's width
  // there: the cells visited follow the beam, not the box around all of it.
  constexpr double kStretch = 0.5;  // m, ten cells of 5 cm
  for (double near = from; near < to; near += kStretch) {
    const double far = std::min(to, near + kStretch);
    const Eigen::Vector2d a = origin + unit * near;
    const Eigen::Vector2d b = origin + unit * far;
    // A cell's position lies in the cell, so the cells of the box hold every
    // position within it.
    const double pad = thin_objects_.halfWidthAt(far, angle_step);
    const CellIndex lo = grid_.cellOf(a.cwiseMin(b).array() - pad);
    const CellIndex hi = grid_.cellOf(a.cwiseMax(b).array() + pad);
    const bool found = cells == CellsThatCount::kObstacles
                           ? grid_.anyObstacleIn(lo, hi, holds)
                           : grid_.anyCellHoldingIn(lo, hi, params_.thin_object_min_returns, holds);
    if (found) return true;
  }
  return false;
}

bool PenetrationFilter::objectInFootprint(const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                                          double angle_step) const {
  const double length = (p - origin).norm();
  if (!(length > 0.0)) return false;
  // Cells holding thin_object_min_returns count (obs_th until Beyond the
  // paper 32; an obstacle needs more): most of a thin leg's returns are
  // mixed and land elsewhere, and the cache kept few on the leg itself.
  return anyCellAlongBeam(origin, (p - origin) / length, 0.0, length - thin_objects_.depthStep(), angle_step,
                          CellsThatCount::kThinObjectCells, [&](const Eigen::Vector2d& q) {
                            return thin_objects_.inFootprintInFront(origin, p, q, angle_step);
                          });
}

bool PenetrationFilter::obstacleBehindInFootprint(const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                                                  double angle_step, double range_max) const {
  const double length = (p - origin).norm();
  // A sensor without a finite range gives no end to the walk: nothing is sought.
  if (!(length > 0.0) || !std::isfinite(range_max)) return false;
  // An obstacle (more than obs_th returns), not the weaker cells in front:
  // with those, thin legs seen past another near the range's end were lost
  // (docs/accuracy.md, 30).
  return anyCellAlongBeam(origin, (p - origin) / length, length + thin_objects_.depthStep(), range_max, angle_step,
                          CellsThatCount::kObstacles, [&](const Eigen::Vector2d& q) {
                            return thin_objects_.inFootprintBehind(origin, p, q, angle_step, range_max);
                          });
}

void PenetrationFilter::markBeyondRememberedSurfaces(Stamp stamp, const Eigen::Vector2d& origin,
                                                     std::span<std::uint8_t> labels) const {
  const std::function<bool(const MirrorCrossing&)> ghost = [&](const MirrorCrossing& crossing) {
    return mirror_ghosts_.isGhost(crossing, grid_);
  };
  const auto isMirrorGhost = [&](const Eigen::Vector2d& p) {
    return mirror_ghosts_.enabled() &&
           memory_.anyMirrorCrossed(origin, p, stamp, mirror_ghosts_.minDepthBeyondLine(), ghost);
  };
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] != static_cast<std::uint8_t>(PointCode::kValid)) continue;
    if (memory_.liesBeyondASurface(origin, points_[i], stamp) || isMirrorGhost(points_[i]))
      labels[i] = static_cast<std::uint8_t>(PointCode::kMisdetected);
  }
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
