#pragma once
#include <cmath>

#include <Eigen/Core>

#include "scanfilter/penetration_filter_params.hpp"

namespace scanfilter {

// The per-cell test of step 2 (paper steps b-e), shared by both
// implementations so that they agree to the last bit.
class PenetrationRule {
 public:
  explicit PenetrationRule(const PenetrationFilterParams& params)
      : corridor_sq_(params.corridor_half_width * params.corridor_half_width),
        own_margin_(params.own_surface_margin),
        own_margin_per_m_(params.own_surface_margin_per_m),
        behind_sq_(params.behind_margin * params.behind_margin) {}

  // Squared own-surface margin for a beam of length `length` (m).
  double ownMarginSq(double length) const {
    const double m = own_margin_ + own_margin_per_m_ * length;
    return m * m;
  }

  // Which side of the beam r->p a penetrating obstacle lies on.
  enum Side : unsigned { kNone = 0, kLeft = 1, kRight = 2, kBothSides = kLeft | kRight };

  // The side of the beam on which obstacle position q makes the point p, seen
  // from sensor r, a misdetection; kNone when it does not. `own_sq` is
  // ownMarginSq(|p - r|).
  Side penetrationSide(const Eigen::Vector2d& r, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                       double own_sq) const {
    if (!penetrates(r, p, q, own_sq)) return kNone;
    const Eigen::Vector2d v = p - r, w = q - r;
    return v.x() * w.y() - v.y() * w.x() >= 0.0 ? kLeft : kRight;
  }

  // True when obstacle position q makes the point p, seen from sensor r, a
  // misdetection (steps b-e). `own_sq` is ownMarginSq(|p - r|).
  bool penetrates(const Eigen::Vector2d& r, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                  double own_sq) const {
    const Eigen::Vector2d v = p - r;
    const Eigen::Vector2d w = q - r;
    const double along = v.dot(w);
    if (along <= 0.0) return false;  // (b) |θ1| >= 90°: q is behind the sensor
    const double length_sq = v.squaredNorm();
    const double cross = v.x() * w.y() - v.y() * w.x();
    if (cross * cross > corridor_sq_ * length_sq) return false;  // (c) d1: q is off the beam
    const double d2_sq = (p - q).squaredNorm();
    if (d2_sq < own_sq) return false;  // q is on the surface p lies on
    if (along < length_sq) return true;  // (d) |θ2| < 90°: the beam passes q before p
    return d2_sq < behind_sq_;          // (e) as printed: q just beyond p
  }

  // How far beyond p a penetrating cell can lie, for the beam walk's bounds.
  double corridorHalfWidth() const { return std::sqrt(corridor_sq_); }
  double behindMargin() const { return std::sqrt(behind_sq_); }

 private:
  double corridor_sq_;
  double own_margin_;
  double own_margin_per_m_;
  double behind_sq_;
};

}  // namespace scanfilter
