#pragma once
#include <functional>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/penetration_rule.hpp"

namespace scanfilter {

// Collects what the obstacle cells along one beam say about its point and
// decides when that is enough to call the point a misdetection.
//
// Paper mode (require_both_sides false): one cell on the beam is enough.
// Both-sides mode: the beam must cross a surface, i.e. pass between two
// obstacle positions on opposite sides of it that are at most `surface_gap`
// apart (neighbouring cells of one wall). Passing beside an edge, a door
// jamb or a leg leaves all of them on one side; passing between two objects
// leaves them too far apart. The result does not depend on the order the
// cells come in, so both implementations agree.
class PenetrationEvidence {
 public:
  // Whether the obstacles at a and b, neighbours across a beam, are part of
  // a surface that goes on past them (empty: any two are).
  using SurfaceGoesOn = std::function<bool(const Eigen::Vector2d& a, const Eigen::Vector2d& b)>;

  PenetrationEvidence(const PenetrationRule& rule, double surface_gap, SurfaceGoesOn goes_on = {})
      : rule_(rule), gap_sq_(surface_gap * surface_gap), goes_on_(std::move(goes_on)) {}

  void reset() {
    left_.clear();
    right_.clear();
  }

  // Adds the evidence `bits` of the obstacle at q; true once conclusive.
  bool add(unsigned bits, const Eigen::Vector2d& q) {
    if (bits == PenetrationRule::kNone) return false;
    if (!rule_.requiresBothSides()) return (bits & PenetrationRule::kOnBeam) != 0;
    const bool left = (bits & PenetrationRule::kLeft) != 0;
    for (const auto& other : left ? right_ : left_)
      if ((other - q).squaredNorm() <= gap_sq_ && (!goes_on_ || goes_on_(other, q))) return true;
    (left ? left_ : right_).push_back(q);
    return false;
  }

 private:
  const PenetrationRule& rule_;
  double gap_sq_;
  SurfaceGoesOn goes_on_;
  std::vector<Eigen::Vector2d> left_;
  std::vector<Eigen::Vector2d> right_;
};

}  // namespace scanfilter
