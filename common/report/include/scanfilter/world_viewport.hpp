#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace scanfilter {

// World metres to image pixels, y up: a box in the world scaled so its longer
// side spans `longer_side_pixels`. What every picture of points uses.
class WorldViewport {
 public:
  WorldViewport(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi, int longer_side_pixels) : lo_(lo) {
    const Eigen::Vector2d extent = (hi - lo).cwiseMax(kMinExtent);
    scale_ = longer_side_pixels / std::max(extent.x(), extent.y());
    width_ = static_cast<int>(extent.x() * scale_) + 1;
    height_ = static_cast<int>(extent.y() * scale_) + 1;
  }

  int width() const { return width_; }
  int height() const { return height_; }
  int px(const Eigen::Vector2d& p) const { return static_cast<int>((p.x() - lo_.x()) * scale_); }
  int py(const Eigen::Vector2d& p) const { return height_ - 1 - static_cast<int>((p.y() - lo_.y()) * scale_); }

 private:
  static constexpr double kMinExtent = 1e-3;  // m: a box of one point still has a scale
  Eigen::Vector2d lo_;
  double scale_ = 1.0;
  int width_ = 1;
  int height_ = 1;
};

// The box around the points a picture will show; a viewport of it (a box of
// nothing is the origin).
class WorldBounds {
 public:
  void include(const Eigen::Vector2d& p) { lo_ = lo_.cwiseMin(p), hi_ = hi_.cwiseMax(p); }
  WorldViewport viewport(int longer_side_pixels) const {
    if (!std::isfinite(lo_.x())) return {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(), longer_side_pixels};
    return {lo_, hi_, longer_side_pixels};
  }

 private:
  Eigen::Vector2d lo_ = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi_ = -lo_;
};

}  // namespace scanfilter
