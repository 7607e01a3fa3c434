#pragma once
#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "scanfilter/penetration_filter_params.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

// The per-cell test of step 2 (paper steps b-e), shared by both
// implementations so that they agree to the last bit.
class PenetrationRule {
 public:
  // What one obstacle position says about a point, as bits: on which side of
  // the beam it lies (within the straddle width), and whether it lies within
  // the corridor (on the beam).
  enum Evidence : unsigned { kNone = 0, kLeft = 1, kRight = 2, kOnBeam = 4 };

  explicit PenetrationRule(const PenetrationFilterParams& params)
      : corridor_sq_(params.corridor_half_width * params.corridor_half_width),
        outer_(params.require_both_sides ? params.straddle_half_width : params.corridor_half_width),
        own_margin_(params.own_surface_margin),
        own_margin_per_m_(params.own_surface_margin_per_m),
        behind_sq_(params.behind_margin * params.behind_margin),
        require_both_sides_(params.require_both_sides) {}

  // Own-surface margin for a beam of length `length` (m), and its square.
  double ownMargin(double length) const { return own_margin_ + own_margin_per_m_ * length; }
  double ownMarginSq(double length) const {
    const double m = ownMargin(length);
    return m * m;
  }

  // Evidence of obstacle position q against the point p seen from sensor r
  // (steps b-e; `own_sq` is ownMarginSq(|p - r|)); kNone when q says nothing.
  unsigned evidence(const Eigen::Vector2d& r, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                    double own_sq) const {
    const Eigen::Vector2d v = p - r;
    const Eigen::Vector2d w = q - r;
    const double along = v.dot(w);
    if (along <= 0.0) return kNone;  // (b) |θ1| >= 90°: q is behind the sensor
    const double length_sq = v.squaredNorm();
    const double cross = v.x() * w.y() - v.y() * w.x();
    const double d1_sq_scaled = cross * cross;  // d1² · |v|²
    if (d1_sq_scaled > outer_ * outer_ * length_sq) return kNone;  // (c) q is off the beam
    const double d2_sq = (p - q).squaredNorm();
    if (d2_sq < own_sq) return kNone;  // q is on the surface p lies on
    // (d) |θ2| < 90°: the beam passes q before p; (e) as printed: q just beyond p.
    if (along >= length_sq && d2_sq >= behind_sq_) return kNone;
    unsigned bits = cross >= 0.0 ? kLeft : kRight;
    if (d1_sq_scaled <= corridor_sq_ * length_sq) bits |= kOnBeam;
    return bits;
  }

  // Test (c) alone, for many cells against one beam (the fast step 2): the
  // beam's limit once, then one cross product a cell, no branch. Loosened by
  // kNearBeamSlack, so that it holds for every q evidence() counts whatever
  // the rounding: both compute the same expressions, and in an ISO C++ build
  // (no contraction into fused multiply-adds) agree to the bit anyway.
  static constexpr double kNearBeamSlack = 1e-9;  // relative
  double nearBeamLimit(const Eigen::Vector2d& v) const {  // v = p - r
    return outer_ * outer_ * v.squaredNorm() * (1.0 + kNearBeamSlack);
  }
  static bool nearBeam(const Eigen::Vector2d& v, const Eigen::Vector2d& w, double limit) {  // w = q - r
    const double off = cross(v, w);  // |v| times q's distance off the beam
    return off * off <= limit;
  }

  bool requiresBothSides() const { return require_both_sides_; }

  // How far off the beam and beyond its point evidence can lie: the beam
  // walk's bounds.
  double outerHalfWidth() const { return outer_; }
  double behindMargin() const { return std::sqrt(behind_sq_); }

  // How far along a beam of length `length` (from the sensor) evidence can
  // lie, for a point with own-surface margin² `own_sq`. A q within outer_ of
  // the beam and projecting at t has |p - q|² <= (length - t)² + outer_², so
  // beyond length - sqrt(own² - outer_²) it is always on p's own surface:
  // the beam walk stops there instead of walking that surface's cells.
  double reachAlongBeam(double length, double own_sq) const {
    if (behind_sq_ > own_sq) return length + behindMargin();  // step (e) reaches past p
    const double outer_sq = outer_ * outer_;
    if (own_sq <= outer_sq) return length;
    return length - std::sqrt(own_sq - outer_sq);
  }

 private:
  double corridor_sq_;
  double outer_;
  double own_margin_;
  double own_margin_per_m_;
  double behind_sq_;
  bool require_both_sides_;
};

}  // namespace scanfilter
