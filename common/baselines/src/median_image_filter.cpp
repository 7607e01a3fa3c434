#include "scanfilter/baselines/median_image_filter.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/cell_key.hpp"

namespace scanfilter::baselines {

namespace {
constexpr int kMaxGrey = 255;  // an 8-bit grey image
}

MedianImageFilter::MedianImageFilter(const MedianImageParams& params) : params_(params) {}

MedianImageFilter::CellKey MedianImageFilter::key(std::int32_t x, std::int32_t y) {
  return cellKey(x, y);
}

std::int32_t MedianImageFilter::cellIndex(double coordinate) const {
  return static_cast<std::int32_t>(std::floor(coordinate / params_.cell_size));
}

MedianImageFilter::CellKey MedianImageFilter::cellOf(const Eigen::Vector2d& p) const {
  return key(cellIndex(p.x()), cellIndex(p.y()));
}

void MedianImageFilter::addFrame(const std::vector<CellKey>& cells, int delta) {
  for (CellKey c : cells) {
    auto it = hits_.try_emplace(c, 0).first;
    it->second += delta;
    if (it->second == 0) hits_.erase(it);
  }
}

int MedianImageFilter::greyAt(std::int32_t x, std::int32_t y) const {
  const auto it = hits_.find(key(x, y));
  return it == hits_.end() ? 0 : std::min(it->second, kMaxGrey);
}

int MedianImageFilter::smoothedGrey(const Eigen::Vector2d& p) {
  const std::int32_t cx = cellIndex(p.x()), cy = cellIndex(p.y());
  const int half = params_.window / 2;
  window_values_.clear();
  for (int dy = -half; dy <= half; ++dy)
    for (int dx = -half; dx <= half; ++dx) {
      const int grey = greyAt(cx + dx, cy + dy);
      if (grey > 0 || !params_.ignore_empty) window_values_.push_back(grey);
    }
  if (window_values_.empty()) return 0;
  auto mid = window_values_.begin() + static_cast<std::ptrdiff_t>(window_values_.size() / 2);
  std::nth_element(window_values_.begin(), mid, window_values_.end());
  return *mid;
}

void MedianImageFilter::apply(const Scan& scan, const SensorInfo& sensor, std::span<std::uint8_t> labels) {
  labelReturns(scan, labels);
  worldPoints(scan, sensor, directions_, points_);
  std::vector<CellKey> cells;
  cells.reserve(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (scan.hasReturn(i)) cells.push_back(cellOf(points_[i]));
  addFrame(cells, +1);
  frames_.push_back(std::move(cells));
  while (static_cast<int>(frames_.size()) > params_.frames) {
    addFrame(frames_.front(), -1);
    frames_.pop_front();
  }
  for (std::size_t i = 0; i < scan.size(); ++i)
    if (scan.hasReturn(i) && smoothedGrey(points_[i]) < params_.threshold)
      labels[i] = static_cast<std::uint8_t>(PointCode::kMisdetected);
}

}  // namespace scanfilter::baselines
