#include "scanfilter/surface_memory.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

std::optional<double> SurfaceMemory::Segment::crossingAlong(const Eigen::Vector2d& p0,
                                                            const Eigen::Vector2d& p1) const {
  const double d0 = normal.dot(p0 - a), d1 = normal.dot(p1 - a);
  if ((d0 > 0.0) == (d1 > 0.0)) return std::nullopt;
  return unit.dot(p0 + (p1 - p0) * (d0 / (d0 - d1)) - a);
}

SurfaceMemory::SurfaceMemory(const SurfaceMemoryParams& params)
    : params_(params), drift_heading_per_m_(std::tan(degreesToRadians(params.drift_margin_deg_per_m))) {}

void SurfaceMemory::clear() {
  segments_.clear();
  path_ = 0.0;
  path_anchor_.reset();
  last_remembered_.reset();
  last_origin_.reset();
}

double SurfaceMemory::lifetimeOf(const Segment& s) const {
  // A confirmed pane or mirror never lives shorter than lifetime: with
  // specular_lifetime at most that, none is confirmed (confirmPanesAndMirrors).
  if (s.pane_or_mirror) return params_.specular_lifetime;
  // Found in the cache (a line of single returns) and not confirmed: no
  // surer than the cache it was found in, and a thin leg's mixed returns
  // line up too (Beyond the paper 40).
  return s.sparse ? params_.sparse_lifetime : params_.lifetime;
}

void SurfaceMemory::forget(const Eigen::Vector2d& origin, Stamp now) {
  drop([&](const Segment& s) { return !alive(s, now); });
  if (last_origin_) {
    const Eigen::Vector2d from = *last_origin_;
    drop([&](const Segment& s) {
      const std::optional<double> along = s.crossingAlong(from, origin);
      return along && *along >= 0.0 && *along <= s.length;
    });
  }
  last_origin_ = origin;
  if (!path_anchor_) path_anchor_ = origin;
  if (const double step = (origin - *path_anchor_).norm(); step >= kPathStep) {
    path_ += step;
    path_anchor_ = origin;
  }
}

void SurfaceMemory::drop(const std::function<bool(const Segment&)>& gone) {
  std::vector<Segment> dropped;
  std::erase_if(segments_, [&](const Segment& s) {
    if (!gone(s)) return false;
    dropped.push_back(s);
    return true;
  });
  endWhereJoinsWent(dropped);
}

void SurfaceMemory::endWhereJoinsWent(const std::vector<Segment>& dropped) {
  // A piece's end without a margin joined another piece; with that piece
  // gone it is an end again. The pieces of one merge meet exactly, and a
  // later merge moves a piece onto the new line by at most merge_offset, so
  // an end that near a dropped piece's end gets its margin back (where it
  // also joins a piece that stays, that costs the margin's blind stretch).
  if (dropped.empty()) return;
  const double near_sq = params_.merge_offset * params_.merge_offset;
  const auto joinedDropped = [&](const Eigen::Vector2d& end) {
    return std::any_of(dropped.begin(), dropped.end(), [&](const Segment& d) {
      return (d.a - end).squaredNorm() <= near_sq || (d.b() - end).squaredNorm() <= near_sq;
    });
  };
  for (Segment& s : segments_) {
    if (s.margin_a == 0.0 && joinedDropped(s.a)) s.margin_a = params_.end_margin;
    if (s.margin_b == 0.0 && joinedDropped(s.b())) s.margin_b = params_.end_margin;
  }
}

bool SurfaceMemory::beamPassesThrough(const Segment& s, const Eigen::Vector2d& origin, const Eigen::Vector2d& p,
                                      double surface_margin) const {
  // A return near the line lies on the surface (noise, pose error).
  if (std::abs(s.normal.dot(p - s.a)) < surface_margin) return false;
  const std::optional<double> along = s.crossingAlong(origin, p);
  return along && s.insideEnds(*along);
}

std::optional<SurfaceMemory::Held> SurfaceMemory::heldNear(const Eigen::Vector2d& p, Stamp now,
                                                           double radius) const {
  std::optional<Held> held;
  for (const Segment& s : segments_) {
    const double along = s.unit.dot(p - s.a);
    if (along < 0.0 || along > s.length || std::abs(s.normal.dot(p - s.a)) > radius) continue;
    const Held h{alive(s, now), s.pane_or_mirror};
    // A live segment says more than a dead one, a confirmed one more than not.
    if (!held || std::pair(h.alive, h.pane_or_mirror) > std::pair(held->alive, held->pane_or_mirror)) held = h;
  }
  return held;
}

double SurfaceMemory::surfaceMargin(double range) const {
  return params_.surface_margin + params_.surface_margin_per_m * range;
}

double SurfaceMemory::marginOf(const Segment& s, double range) const {
  return surfaceMargin(range) + driftMargin(s, range);
}

double SurfaceMemory::driftMargin(const Segment& s, double range) const {
  // Odometry drifts with the path driven: the position by a share of it,
  // the heading by an angle per metre, which moves a return at `range` by
  // range times that angle. The frames' alignment to the cache corrects the
  // drift only relative to frames of the last seconds.
  // Only a pane or a mirror lives long enough for it to matter; a wall's
  // margin growing too lost more re-observed returns on a Mines log with
  // added drift (docs/beyond-the-paper.md, 34).
  if (!s.pane_or_mirror) return 0.0;
  return (params_.drift_margin_per_m + drift_heading_per_m_ * range) * (path_ - s.path_when_seen);
}

bool SurfaceMemory::liesBeyondASurface(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, Stamp now) const {
  const double range = (p - origin).norm();
  const Eigen::Vector2d lo = origin.cwiseMin(p), hi = origin.cwiseMax(p);
  return std::any_of(segments_.begin(), segments_.end(), [&](const Segment& s) {
    const bool boxes_meet = (s.hi.array() >= lo.array()).all() && (s.lo.array() <= hi.array()).all();
    return boxes_meet && alive(s, now) && beamPassesThrough(s, origin, p, marginOf(s, range));
  });
}

bool SurfaceMemory::anyMirrorCrossed(const Eigen::Vector2d& origin, const Eigen::Vector2d& p, Stamp now,
                                     double min_depth, const std::function<bool(const MirrorCrossing&)>& pred) const {
  const double range = (p - origin).norm();
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const Segment& s = segments_[k];
    if (!s.pane_or_mirror || !alive(s, now)) continue;
    const double beyond = s.normal.dot(p - s.a);
    if (!(std::abs(beyond) >= min_depth + driftMargin(s, range))) continue;  // on the line (NaN too)
    const std::optional<double> along = s.crossingAlong(origin, p);  // nullopt: p on the sensor's side
    if (!along) continue;
    const double past_end = std::max(-*along, *along - s.length);
    if (pred({s.a + s.unit * *along, s.unit, p - 2.0 * beyond * s.normal, s.insideEnds(*along), k, past_end}))
      return true;
  }
  return false;
}

bool SurfaceMemory::seenThroughHeadOn(const Segment& s, std::span<const Eigen::Vector2d> points,
                                      const BeamMask& returns, const Eigen::Vector2d& origin) const {
  // Only a segment the sensor faces, the foot of its perpendicular inside
  // it. Head-on beams reach distance · tan(head_on_deg) beyond the foot, but
  // counting those past a segment's end too lost more re-observed returns on
  // the Mines logs (docs/beyond-the-paper.md, 26). Written so that NaN skips it.
  if (!s.insideEnds(s.unit.dot(origin - s.a))) return false;
  const double max_along = std::sin(degreesToRadians(params_.head_on_deg));
  int through = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!returns[i]) continue;
    const Eigen::Vector2d& p = points[i];
    const Eigen::Vector2d beam = p - origin;
    const double length = beam.norm();
    if (!(length > 0.0) || std::abs(s.unit.dot(beam)) > max_along * length) continue;  // not head-on
    // As when judging: a drifted pane's own head-on returns lie on it.
    const double margin = marginOf(s, length);
    if (std::abs(s.normal.dot(p - s.a)) < margin) {
      const double along_line = s.unit.dot(p - s.a);
      if (along_line > 0.0 && along_line < s.length) return false;  // a return on it: it is still there
      continue;
    }
    through += beamPassesThrough(s, origin, p, margin);
  }
  return through >= params_.head_on_through_beams;
}

bool SurfaceMemory::confirmedHeadOn(const Segment& s, std::span<const Eigen::Vector2d> points,
                                    const BeamMask& returns, const Eigen::Vector2d& origin) const {
  const double foot = s.unit.dot(origin - s.a);
  if (!(foot >= 0.0 && foot <= s.length)) return false;  // the frame does not face it (NaN too)
  const double near = params_.specular_confirm_distance;
  const double lobe = std::abs(s.normal.dot(origin - s.a)) * std::tan(degreesToRadians(params_.head_on_deg)) + near;
  int in_lobe = 0, on_off_lobe = 0, through_off_lobe = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!returns[i]) continue;
    const Eigen::Vector2d& p = points[i];
    if (std::abs(s.normal.dot(p - s.a)) <= near) {
      const double along = s.unit.dot(p - s.a);
      if (along < 0.0 || along > s.length) continue;
      ++(std::abs(along - foot) > lobe ? on_off_lobe : in_lobe);
      continue;
    }
    const std::optional<double> crossing = s.crossingAlong(origin, p);
    through_off_lobe += crossing && *crossing >= 0.0 && *crossing <= s.length && std::abs(*crossing - foot) > lobe;
  }
  return in_lobe > 0 && through_off_lobe >= kMinBeamsThroughOffLobe &&
         through_off_lobe >= params_.specular_min_pass_share * (through_off_lobe + on_off_lobe);
}

void SurfaceMemory::confirmPanesAndMirrors(std::span<const Eigen::Vector2d> points, const BeamMask& returns,
                                           const Eigen::Vector2d& origin) {
  if (params_.specular_lifetime <= params_.lifetime) return;  // the rule is off: panes live as long as walls
  for (Segment& s : segments_)
    if (s.sparse && !s.pane_or_mirror) s.pane_or_mirror = confirmedHeadOn(s, points, returns, origin);
}

void SurfaceMemory::forgetSeenThroughHeadOn(std::span<const Eigen::Vector2d> points, const BeamMask& returns,
                                            const Eigen::Vector2d& origin) {
  if (params_.head_on_through_beams <= 0) return;
  drop([&](const Segment& s) { return seenThroughHeadOn(s, points, returns, origin); });
}

SurfaceMemory::Segment SurfaceMemory::segmentBetween(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                                     Stamp last_seen, double margin_a, double margin_b,
                                                     const Eigen::Vector2d& direction_if_a_point) const {
  const double length = (b - a).norm();
  const Eigen::Vector2d unit = length > 0.0 ? Eigen::Vector2d((b - a) / length) : direction_if_a_point;
  return {a, unit, {-unit.y(), unit.x()}, length, a.cwiseMin(b), a.cwiseMax(b), last_seen, margin_a, margin_b};
}

std::vector<SurfaceMemory::Fresh> SurfaceMemory::facingSegments(std::span<const StraightSegment> found,
                                                                const Eigen::Vector2d& origin, Stamp stamp,
                                                                double min_beam_surface_angle_deg) const {
  const double min_sin = std::sin(degreesToRadians(min_beam_surface_angle_deg));
  std::vector<Fresh> fresh;
  for (const StraightSegment& s : found) {
    // The finders make none shorter than their min_length > 0: never a point.
    const Segment segment =
        segmentBetween(s.a, s.b, stamp, params_.end_margin, params_.end_margin, Eigen::Vector2d::UnitX());
    const Eigen::Vector2d to_middle = ((s.a + s.b) / 2 - origin).normalized();
    // The sine of the angle at which the beam to its middle meets it.
    if (std::abs(cross(to_middle, segment.unit)) < min_sin) continue;
    fresh.push_back({segment, s.a_seen_past, s.b_seen_past});
    fresh.back().segment.path_when_seen = path_;
  }
  return fresh;
}

bool SurfaceMemory::seenAgain(const Segment& now, const Segment& old) const {
  if (std::abs(now.unit.dot(old.unit)) < std::cos(degreesToRadians(params_.merge_angle_deg))) return false;
  if (std::abs(old.normal.dot(now.a - old.a)) > params_.merge_offset ||
      std::abs(old.normal.dot(now.b() - old.a)) > params_.merge_offset)
    return false;
  const double t0 = old.unit.dot(now.a - old.a), t1 = old.unit.dot(now.b() - old.a);
  return std::min(std::max(t0, t1), old.length) > std::max(std::min(t0, t1), 0.0);  // they overlap
}

std::vector<SurfaceMemory::Segment> SurfaceMemory::merged(const Fresh& fresh, const std::vector<Segment>& olds) const {
  const Segment& now = fresh.segment;
  // The line: through the new segment's middle (the latest pose), in the
  // direction of all of them weighted by length (a short new piece is the
  // least sure of its direction).
  Eigen::Vector2d direction = now.unit * now.length;
  for (const Segment& old : olds) direction += (old.unit.dot(now.unit) >= 0.0 ? old.unit : -old.unit) * old.length;
  direction.normalize();
  const Eigen::Vector2d middle = now.a + now.unit * (now.length / 2);
  const double now_a = direction.dot(now.a - middle), now_b = direction.dot(now.b() - middle);
  const double seen_lo = std::min(now_a, now_b), seen_hi = std::max(now_a, now_b);
  double lo = seen_lo, hi = seen_hi;
  // The margins of the old ends that lie beyond: an old end where it joined
  // a stretch remembered from another time has none, and keeps none.
  double lo_margin = params_.end_margin, hi_margin = params_.end_margin;
  Stamp remembered = olds.front().last_seen;
  for (const Segment& old : olds) {
    remembered = std::max(remembered, old.last_seen);
    for (const auto& [end, margin] : {std::pair{old.a, old.margin_a}, std::pair{old.b(), old.margin_b}}) {
      const double u = direction.dot(end - middle);
      if (u < lo) {
        lo = u;
        lo_margin = margin;
      }
      if (u > hi) {
        hi = u;
        hi_margin = margin;
      }
    }
  }
  // Where the new frame saw past an end, the surface ends there now.
  const bool lo_seen_past = now_a < now_b ? fresh.a_seen_past : fresh.b_seen_past;
  const bool hi_seen_past = now_a < now_b ? fresh.b_seen_past : fresh.a_seen_past;
  if (lo_seen_past) lo = seen_lo;
  if (hi_seen_past) hi = seen_hi;
  // The stretch seen now is new; what lies beyond it keeps the newest time
  // any of the old segments was seen, and joins it without an end margin.
  // An old end beyond by a rounding error only leaves a piece of (next to)
  // length 0 that takes its margin and never merges again: an end seen
  // again keeps no margin. Giving it back cost recall on every sensor
  // preset (docs/accuracy-investigations.md, "The surface memory's end
  // margins wear away"). A piece of length 0 keeps the line's direction.
  const auto piece = [&](double from, double to, Stamp last_seen, double margin_from, double margin_to) {
    return segmentBetween(middle + direction * from, middle + direction * to, last_seen, margin_from, margin_to,
                          direction);
  };
  const double end = params_.end_margin;
  std::vector<Segment> out{
      piece(seen_lo, seen_hi, now.last_seen, lo < seen_lo ? 0.0 : end, hi > seen_hi ? 0.0 : end)};
  if (lo < seen_lo) out.push_back(piece(lo, seen_lo, remembered, lo_margin, 0.0));
  if (hi > seen_hi) out.push_back(piece(seen_hi, hi, remembered, 0.0, hi_margin));
  // One surface: what any piece was known to be, all are; the stretches
  // beyond the new one were last seen when the newest old piece was.
  bool sparse = now.sparse, pane_or_mirror = now.pane_or_mirror;
  double old_path = olds.front().path_when_seen;
  for (const Segment& old : olds) {
    sparse = sparse || old.sparse;
    pane_or_mirror = pane_or_mirror || old.pane_or_mirror;
    old_path = std::max(old_path, old.path_when_seen);
  }
  for (Segment& piece : out) {
    piece.sparse = sparse;
    piece.pane_or_mirror = pane_or_mirror;
    piece.path_when_seen = old_path;
  }
  out.front().path_when_seen = now.path_when_seen;
  return out;
}

bool SurfaceMemory::remember(std::span<const Eigen::Vector2d> points, const BeamMask& usable,
                             const Eigen::Vector2d& origin, Stamp stamp, bool full_turn,
                             const SurfaceAcrossGap& surface_across_gap) {
  // A stamp that did not advance is no clock (as in step 2's cache): remembered.
  if (last_remembered_) {
    const double since = stamp.secondsSince(*last_remembered_);
    if (since > 0.0 && since < params_.min_interval) return false;
  }
  last_remembered_ = stamp;
  mergeIn(facingSegments(straightSegments(points, usable, origin, params_.segments, full_turn, surface_across_gap),
                         origin, stamp, params_.min_beam_surface_angle_deg));
  return true;
}

void SurfaceMemory::rememberSegments(std::span<const StraightSegment> found, const Eigen::Vector2d& origin,
                                     Stamp stamp, double min_beam_surface_angle_deg) {
  std::vector<Fresh> fresh = facingSegments(found, origin, stamp, min_beam_surface_angle_deg);
  for (Fresh& f : fresh) f.segment.sparse = true;
  mergeIn(fresh);
}

void SurfaceMemory::mergeIn(const std::vector<Fresh>& fresh_segments) {
  std::vector<Segment> added;
  for (const Fresh& fresh : fresh_segments) {
    std::vector<Segment> olds;
    std::erase_if(segments_, [&](const Segment& old) {
      if (!seenAgain(fresh.segment, old)) return false;
      olds.push_back(old);
      return true;
    });
    if (olds.empty()) {
      added.push_back(fresh.segment);
    } else {
      const std::vector<Segment> pieces = merged(fresh, olds);
      added.insert(added.end(), pieces.begin(), pieces.end());
    }
  }
  segments_.insert(segments_.end(), added.begin(), added.end());
  keepWithinBound();
}

void SurfaceMemory::keepWithinBound() {
  if (segments_.size() <= params_.max_segments) return;
  // The most recently seen first; the rest go.
  std::stable_sort(segments_.begin(), segments_.end(),
                   [](const Segment& x, const Segment& y) { return y.last_seen < x.last_seen; });
  const std::vector<Segment> dropped(segments_.begin() + static_cast<std::ptrdiff_t>(params_.max_segments),
                                     segments_.end());
  segments_.resize(params_.max_segments);
  endWhereJoinsWent(dropped);
}

}  // namespace scanfilter
