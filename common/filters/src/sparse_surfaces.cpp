#include "scanfilter/sparse_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <utility>

#include "scanfilter/floor_to_int.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {
namespace {

// The cells by position: a dense rectangle over their bounds, so that
// looking up a neighbour costs an array read (the cells of one frame's
// reach, a few thousand in a rectangle of some ten thousand).
class CellRaster {
 public:
  CellRaster(std::span<const CellMean> cells, double cell_size) {
    positions_.reserve(cells.size());
    for (const CellMean& c : cells)
      positions_.emplace_back(floorToInt(c.at.x() / cell_size), floorToInt(c.at.y() / cell_size));
    x0_ = y0_ = 0;
    int x1 = -1, y1 = -1;
    if (!positions_.empty()) {
      x0_ = x1 = positions_.front().first;
      y0_ = y1 = positions_.front().second;
    }
    for (const auto& [x, y] : positions_) {
      x0_ = std::min(x0_, x), x1 = std::max(x1, x);
      y0_ = std::min(y0_, y), y1 = std::max(y1, y);
    }
    width_ = x1 - x0_ + 1;
    height_ = y1 - y0_ + 1;
    index_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), -1);
    for (std::size_t i = 0; i < positions_.size(); ++i)
      index_[offset(positions_[i].first, positions_[i].second)] = static_cast<int>(i);
  }

  // fn(j) for every cell j within `reach` cells of cell i (in x and in y), i itself too.
  template <typename Fn>
  void forEachNear(std::size_t i, int reach, Fn&& fn) const {
    const auto [cx, cy] = positions_[i];
    for (int y = std::max(cy - reach, y0_); y <= std::min(cy + reach, y0_ + height_ - 1); ++y)
      for (int x = std::max(cx - reach, x0_); x <= std::min(cx + reach, x0_ + width_ - 1); ++x)
        if (const int j = index_[offset(x, y)]; j >= 0) fn(static_cast<std::size_t>(j));
  }

 private:
  std::size_t offset(int x, int y) const {
    return static_cast<std::size_t>(y - y0_) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x - x0_);
  }

  std::vector<std::pair<int, int>> positions_;
  std::vector<int> index_;
  int x0_ = 0, y0_ = 0, width_ = 0, height_ = 0;
};

// The axes of a 2 x 2 covariance in closed form (the general eigensolver
// was a fifth of the step's time): the direction of most spread, the one
// across it, and the variance across.
struct PrincipalAxes {
  Eigen::Vector2d along;
  Eigen::Vector2d across;
  double variance_across = 0.0;
};

PrincipalAxes principalAxes(const Eigen::Matrix2d& covariance) {
  const double a = covariance(0, 0), b = covariance(0, 1), c = covariance(1, 1);
  const double angle = 0.5 * std::atan2(2 * b, a - c);
  const Eigen::Vector2d along(std::cos(angle), std::sin(angle));
  const double half_difference = 0.5 * (a - c);
  const double variance_across = 0.5 * (a + c) - std::sqrt(half_difference * half_difference + b * b);
  return {along, {-along.y(), along.x()}, std::max(0.0, variance_across)};
}

int cellsWithin(double distance, double cell_size) { return static_cast<int>(std::ceil(distance / cell_size)); }

// The direction of the line the cells around sparse cell i lie along, when
// they lie thinly along one that passes through cell i itself.
std::optional<Eigen::Vector2d> localDirection(std::span<const CellMean> cells, const CellRaster& raster,
                                              std::size_t i, double cell_size, const SparseSurfaceParams& params) {
  const Eigen::Vector2d centre = cells[i].at;
  const double radius_sq = params.neighbour_radius * params.neighbour_radius;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  Eigen::Matrix2d products = Eigen::Matrix2d::Zero();
  int n = 0;
  raster.forEachNear(i, cellsWithin(params.neighbour_radius, cell_size), [&](std::size_t j) {
    const Eigen::Vector2d d = cells[j].at - centre;
    if (d.squaredNorm() > radius_sq) return;
    sum += d;
    products += d * d.transpose();
    ++n;
  });
  if (n < params.min_neighbours) return std::nullopt;
  const Eigen::Vector2d mean = sum / n;
  const PrincipalAxes axes = principalAxes(products / n - mean * mean.transpose());
  if (std::sqrt(axes.variance_across) > params.max_thickness) return std::nullopt;
  if (std::abs(axes.across.dot(mean)) > 2 * params.max_thickness) return std::nullopt;  // the cell off that line
  return axes.along;
}

std::size_t rootOf(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Groups of cells with a local line, joined where two lie within max_gap of
// each other, alike in direction, each on the other's line.
std::vector<std::vector<std::size_t>> joinedLines(std::span<const CellMean> cells, const CellRaster& raster,
                                                  const std::vector<std::optional<Eigen::Vector2d>>& direction,
                                                  double cell_size, const SparseSurfaceParams& params) {
  std::vector<std::size_t> parent(cells.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const double min_cos = std::cos(degreesToRadians(params.max_angle_deg));
  const double gap_sq = params.max_gap * params.max_gap;
  const double off_line = 2 * params.max_thickness;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!direction[i]) continue;
    const Eigen::Vector2d normal(-direction[i]->y(), direction[i]->x());
    raster.forEachNear(i, cellsWithin(params.max_gap, cell_size), [&](std::size_t j) {
      if (j <= i || !direction[j]) return;
      const Eigen::Vector2d d = cells[j].at - cells[i].at;
      if (d.squaredNorm() > gap_sq || std::abs(direction[i]->dot(*direction[j])) < min_cos ||
          std::abs(normal.dot(d)) > off_line)
        return;
      parent[rootOf(parent, j)] = rootOf(parent, i);
    });
  }
  std::vector<std::vector<std::size_t>> groups(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (direction[i]) groups[rootOf(parent, i)].push_back(i);
  std::erase_if(groups, [&](const auto& g) { return static_cast<int>(g.size()) < params.min_cells; });
  return groups;
}

// The group's fitted line, cut where its cells lie farther apart than
// max_gap; each piece long, full and straight enough is a surface.
void appendSurfaces(std::span<const CellMean> cells, const std::vector<std::size_t>& group,
                    const SparseSurfaceParams& params, std::vector<StraightSegment>& out) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const std::size_t i : group) mean += cells[i].at;
  mean /= static_cast<double>(group.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const std::size_t i : group) scatter += (cells[i].at - mean) * (cells[i].at - mean).transpose();
  const PrincipalAxes fit = principalAxes(scatter);
  const Eigen::Vector2d along = fit.along, across = fit.across;
  std::vector<std::pair<double, double>> placed;  // (along, across) the fitted line, from the mean
  placed.reserve(group.size());
  for (const std::size_t i : group) placed.emplace_back(along.dot(cells[i].at - mean), across.dot(cells[i].at - mean));
  std::sort(placed.begin(), placed.end());
  std::size_t first = 0;
  for (std::size_t k = 1; k <= placed.size(); ++k) {
    if (k < placed.size() && placed[k].first - placed[k - 1].first <= params.max_gap) continue;
    const double length = placed[k - 1].first - placed[first].first;
    const bool straight = std::all_of(placed.begin() + static_cast<std::ptrdiff_t>(first),
                                      placed.begin() + static_cast<std::ptrdiff_t>(k),
                                      [&](const auto& p) { return std::abs(p.second) <= params.max_deviation; });
    if (static_cast<int>(k - first) >= params.min_cells && length >= params.min_length && straight)
      out.push_back({mean + along * placed[first].first, mean + along * placed[k - 1].first, false, false});
    first = k;
  }
}

}  // namespace

std::vector<StraightSegment> sparseSurfaces(std::span<const CellMean> cells, double cell_size,
                                            const SparseSurfaceParams& params) {
  std::vector<StraightSegment> out;
  if (cells.empty()) return out;
  const CellRaster raster(cells, cell_size);
  std::vector<std::optional<Eigen::Vector2d>> direction(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (cells[i].sparse) direction[i] = localDirection(cells, raster, i, cell_size, params);
  for (const auto& group : joinedLines(cells, raster, direction, cell_size, params))
    appendSurfaces(cells, group, params, out);
  return out;
}

}  // namespace scanfilter
