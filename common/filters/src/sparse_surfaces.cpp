#include "scanfilter/sparse_surfaces.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <optional>
#include <unordered_map>

#include "scanfilter/cell_key.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {
namespace {

// The cells by position. Over a frame's reach indoors (some ten thousand
// cells) a dense rectangle, so that looking up a neighbour costs an array
// read; over a larger one (a 30 m scanner's 1,200 x 1,200 cells) a hash
// map, rather than zeroing megabytes every time.
class CellRaster {
 public:
  static constexpr std::int64_t kMaxDenseCells = 1 << 20;

  explicit CellRaster(std::span<const CellMean> cells) : cells_(cells) {
    if (cells.empty()) return;
    lo_ = hi_ = cells.front().cell;
    for (const CellMean& c : cells) {
      lo_ = {std::min(lo_.x, c.cell.x), std::min(lo_.y, c.cell.y)};
      hi_ = {std::max(hi_.x, c.cell.x), std::max(hi_.y, c.cell.y)};
    }
    width_ = std::int64_t{hi_.x} - lo_.x + 1;
    const std::int64_t height = std::int64_t{hi_.y} - lo_.y + 1;
    dense_ = width_ * height <= kMaxDenseCells;
    if (dense_) index_.assign(static_cast<std::size_t>(width_ * height), -1);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (dense_) index_[offset(cells[i].cell)] = static_cast<int>(i);
      else sparse_index_.emplace(cellKey(cells[i].cell.x, cells[i].cell.y), static_cast<int>(i));
    }
  }

  // fn(j) for every cell j within `reach` cells of cell i (in x and in y), i itself too.
  template <typename Fn>
  void forEachNear(std::size_t i, int reach, Fn&& fn) const {
    const CellIndex c = cells_[i].cell;
    for (std::int32_t y = std::max(c.y - reach, lo_.y); y <= std::min(c.y + reach, hi_.y); ++y)
      for (std::int32_t x = std::max(c.x - reach, lo_.x); x <= std::min(c.x + reach, hi_.x); ++x)
        if (const int j = at({x, y}); j >= 0) fn(static_cast<std::size_t>(j));
  }

 private:
  std::size_t offset(CellIndex c) const {
    return static_cast<std::size_t>((std::int64_t{c.y} - lo_.y) * width_ + (std::int64_t{c.x} - lo_.x));
  }
  int at(CellIndex c) const {
    if (dense_) return index_[offset(c)];
    const auto found = sparse_index_.find(cellKey(c.x, c.y));
    return found == sparse_index_.end() ? -1 : found->second;
  }

  std::span<const CellMean> cells_;
  CellIndex lo_, hi_;
  std::int64_t width_ = 0;
  bool dense_ = true;
  std::vector<int> index_;
  std::unordered_map<std::uint64_t, int> sparse_index_;
};

// The axes of a 2 x 2 covariance in closed form (the general eigensolver
// took 6 % of a replay's time in a profile, a seventh of this step's): the
// direction of most spread, the one across it, and the variance across.
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

// A limit the range noise at a cell widens: `sigmas` σ where that is more
// than `limit`, but no more than `ceiling` (beyond it a leg's blob or a
// scatter of mixed returns would pass for a line).
double widenedByNoise(double limit, double sigmas, double ceiling, double range_noise) {
  // Noise not measured (0), or not a number a sensor could have: the limit
  // as configured, not the ceiling std::min would give for NaN.
  if (!(range_noise > 0.0 && std::isfinite(range_noise))) return limit;
  return std::max(limit, std::min(ceiling, sigmas * range_noise));
}

// How thinly the cells around this one must lie along their line.
double maxThickness(const CellMean& c, const SparseSurfaceParams& params) {
  return widenedByNoise(params.max_thickness, params.max_thickness_noise_sigmas, params.max_thickness_ceiling,
                        c.range_noise);
}

// How far off its surface's fitted line this cell may lie.
double maxDeviation(const CellMean& c, const SparseSurfaceParams& params) {
  return widenedByNoise(params.max_deviation, params.max_deviation_noise_sigmas, params.max_deviation_ceiling,
                        c.range_noise);
}

// How far off a line this cell may lie and still be on it.
double onLineTolerance(const CellMean& c, const SparseSurfaceParams& params) { return 2 * maxThickness(c, params); }

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
    if (!(d.squaredNorm() <= radius_sq)) return;  // NaN too
    sum += d;
    products += d * d.transpose();
    ++n;
  });
  if (n < params.min_neighbours) return std::nullopt;
  const Eigen::Vector2d mean = sum / n;
  const PrincipalAxes axes = principalAxes(products / n - mean * mean.transpose());
  if (!(std::sqrt(axes.variance_across) <= maxThickness(cells[i], params))) return std::nullopt;
  // The cell itself off that line.
  if (!(std::abs(axes.across.dot(mean)) <= onLineTolerance(cells[i], params))) return std::nullopt;
  return axes.along;
}

std::size_t rootOf(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Whether two cells with local lines belong to one surface: near each
// other, alike in direction (|cos| of their angle at least `min_cos`), each
// on the other's line.
bool sameSurface(const CellMean& a, const Eigen::Vector2d& a_direction, const CellMean& b,
                 const Eigen::Vector2d& b_direction, double min_cos, const SparseSurfaceParams& params) {
  const Eigen::Vector2d d = b.at - a.at;
  if (d.squaredNorm() > params.max_gap * params.max_gap) return false;
  if (std::abs(a_direction.dot(b_direction)) < min_cos) return false;
  const auto offLine = [&](const Eigen::Vector2d& direction) { return std::abs(cross(direction, d)); };
  // b off a's line, and a off b's.
  return offLine(a_direction) <= onLineTolerance(b, params) && offLine(b_direction) <= onLineTolerance(a, params);
}

// Groups of at least min_cells cells with a local line, joined pairwise by
// sameSurface; each group in the order of `cells`.
std::vector<std::vector<std::size_t>> joinedLines(std::span<const CellMean> cells, const CellRaster& raster,
                                                  const std::vector<std::optional<Eigen::Vector2d>>& direction,
                                                  double cell_size, const SparseSurfaceParams& params) {
  std::vector<std::size_t> parent(cells.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  const double min_cos = std::cos(degreesToRadians(params.max_angle_deg));
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!direction[i]) continue;
    raster.forEachNear(i, cellsWithin(params.max_gap, cell_size), [&](std::size_t j) {
      if (j > i && direction[j] && sameSurface(cells[i], *direction[i], cells[j], *direction[j], min_cos, params))
        parent[rootOf(parent, j)] = rootOf(parent, i);
    });
  }
  std::vector<std::vector<std::size_t>> groups(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (direction[i]) groups[rootOf(parent, i)].push_back(i);
  std::erase_if(groups, [&](const auto& g) { return static_cast<int>(g.size()) < params.min_cells; });
  return groups;
}

// The group's fitted line from its first cell to its last along it, if the
// group is long enough and every cell lies near that line. Joined cells lie
// within max_gap of each other, so no gap along the line is wider.
std::optional<StraightSegment> fittedSurface(std::span<const CellMean> cells, const std::vector<std::size_t>& group,
                                             const SparseSurfaceParams& params) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const std::size_t i : group) mean += cells[i].at;
  mean /= static_cast<double>(group.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const std::size_t i : group) scatter += (cells[i].at - mean) * (cells[i].at - mean).transpose();
  const PrincipalAxes fit = principalAxes(scatter);
  double first = 0.0, last = 0.0;
  for (const std::size_t i : group) {
    const Eigen::Vector2d offset = cells[i].at - mean;
    if (std::abs(fit.across.dot(offset)) > maxDeviation(cells[i], params)) return std::nullopt;
    first = std::min(first, fit.along.dot(offset));
    last = std::max(last, fit.along.dot(offset));
  }
  if (last - first < params.min_length) return std::nullopt;
  return StraightSegment{mean + fit.along * first, mean + fit.along * last, false, false};
}

}  // namespace

std::vector<StraightSegment> sparseSurfaces(std::span<const CellMean> cells, double cell_size,
                                            const SparseSurfaceParams& params) {
  // A cell without a finite mean takes no part: it is no cell's neighbour
  // (localDirection's distance test fails on NaN) and so gets no line.
  std::vector<StraightSegment> out;
  if (cells.empty()) return out;
  const CellRaster raster(cells);
  std::vector<std::optional<Eigen::Vector2d>> direction(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (cells[i].sparse) direction[i] = localDirection(cells, raster, i, cell_size, params);
  for (const auto& group : joinedLines(cells, raster, direction, cell_size, params))
    if (const auto surface = fittedSurface(cells, group, params)) out.push_back(*surface);
  return out;
}

}  // namespace scanfilter
