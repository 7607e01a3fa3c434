// PenetrationFilter, part 4 of 4: the checks beyond the paper that judge a
// frame's returns after the penetration model: the rescue of step 1's jump
// points (16, 36), the free-space check (17, 19, 39), the thin-object check
// (25, 30-32, 38) and the surface memory with its mirror images (24, 34,
// 35, 43); numbers are the sections of docs/beyond-the-paper.md.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <vector>

#include "return_masks.hpp"
#include "scanfilter/depth_edges.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/thin_object_check.hpp"

namespace scanfilter {

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
  // returns were kept there (docs/beyond-the-paper.md, 31).
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
    if (lone_returns_vote) lone_seen_through_.set(i, mayBeAPanesDirectReturn(origin, points_[i], stands[i], scan));
  }
}

bool PenetrationFilter::mayBeAPanesDirectReturn(const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                                                StandsInFront stands, const Scan& scan) const {
  // Alone in front of both sides (39). A thin object's mixed return has that
  // object in its footprint in front of it (the thin-object check's own
  // test); a pane's direct return has nothing there. Nor was it seen through
  // a pane, or reflected by one (44).
  if (stands != StandsInFront::kOfBothSides || objectInFootprint(origin, p, scan.angle_increment)) return false;
  return params_.free_space_lone_votes_beyond_panes || !seenBeyondAPane(origin, p, scan.stamp);
}

bool PenetrationFilter::seenBeyondAPane(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, Stamp stamp) const {
  if (!memory_.enabled()) return false;
  // 35's depth and line test, whether or not 35 itself marks ghosts
  // (mirror_ghosts.enabled): they say where a pane is, not what a ghost is.
  const double reach = params_.free_space_lone_vote_pane_reach;
  return memory_.anyMirrorCrossed(origin, p, stamp, mirror_ghosts_.minDepthBeyondLine(),
                                  [&](const MirrorCrossing& crossing) {
                                    return mirror_ghosts_.mirrorWithin(crossing, grid_, reach);
                                  });
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
  // (docs/beyond-the-paper.md, 30).
  return anyCellAlongBeam(origin, (p - origin) / length, length + thin_objects_.depthStep(), range_max, angle_step,
                          CellsThatCount::kObstacles, [&](const Eigen::Vector2d& q) {
                            return thin_objects_.inFootprintBehind(origin, p, q, angle_step, range_max);
                          });
}

template <typename Beyond>
void PenetrationFilter::markKeptReturnsWhere(std::span<std::uint8_t> labels, Beyond&& beyond) const {
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels[i] == static_cast<std::uint8_t>(PointCode::kValid) && beyond(points_[i]))
      labels[i] = static_cast<std::uint8_t>(PointCode::kMisdetected);
}

void PenetrationFilter::markBeyondRememberedSurfaces(Stamp stamp, const Eigen::Vector2d& origin,
                                                     std::span<std::uint8_t> labels) const {
  const double min_depth = mirror_ghosts_.minDepthBeyondLine();
  const bool proof_counts = mirror_ghosts_.marksBeyondProvenMirrors();
  // The remembered panes and mirrors this frame found a ghost in (43): sized
  // at the first ghost, so empty while none is proven.
  std::vector<bool> proven;
  const std::function<bool(const MirrorCrossing&)> ghost = [&](const MirrorCrossing& crossing) {
    if (!mirror_ghosts_.isGhost(crossing, grid_)) return false;
    if (proven.empty()) proven.assign(memory_.size(), false);
    assert(crossing.surface < proven.size());  // the memory does not change while a frame is judged
    proven[crossing.surface] = true;
    return true;
  };
  // For the proof alone: a beam through a mirror already proven proves no
  // other, and needs no image test.
  const std::function<bool(const MirrorCrossing&)> proven_or_ghost = [&](const MirrorCrossing& crossing) {
    return (crossing.surface < proven.size() && proven[crossing.surface]) || ghost(crossing);
  };
  markKeptReturnsWhere(labels, [&](const Eigen::Vector2d& p) {
    if (memory_.liesBeyondASurface(origin, p, stamp)) {
      // It goes either way, but a ghost there proves its mirror too (43).
      if (proof_counts) memory_.anyMirrorCrossed(origin, p, stamp, min_depth, proven_or_ghost);
      return true;
    }
    return mirror_ghosts_.enabled() && memory_.anyMirrorCrossed(origin, p, stamp, min_depth, ghost);
  });
  if (proven.empty() || !proof_counts) return;
  // As deep beyond the line as a ghost must be: nearer, a return may be the
  // mirror's own, scattered by noise, or its frame's.
  const std::function<bool(const MirrorCrossing&)> seen_through_proven = [&](const MirrorCrossing& crossing) {
    return mirror_ghosts_.seenThroughProven(crossing, proven, grid_);
  };
  markKeptReturnsWhere(labels, [&](const Eigen::Vector2d& p) {
    return memory_.anyMirrorCrossed(origin, p, stamp, min_depth, seen_through_proven);
  });
}

}  // namespace scanfilter
