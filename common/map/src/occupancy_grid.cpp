#include "scanfilter/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>

#include "scanfilter/cell_key.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

namespace {
float logit(double p) { return static_cast<float>(std::log(p / (1.0 - p))); }
double probabilityOf(float l) { return 1.0 - 1.0 / (1.0 + std::exp(static_cast<double>(l))); }
constexpr int kRosOccupied = 100;
constexpr int kRosUnknown = -1;

std::uint64_t tileKey(CellIndex c, int bits) {
  return cellKey(c.x >> bits, c.y >> bits);
}
std::size_t slotOf(CellIndex c, int side) {
  return static_cast<std::size_t>((c.y & (side - 1)) * side + (c.x & (side - 1)));
}
}  // namespace

void CellBox::include(CellIndex c) {
  if (empty()) {
    lo = hi = c;
    return;
  }
  lo = {std::min(lo.x, c.x), std::min(lo.y, c.y)};
  hi = {std::max(hi.x, c.x), std::max(hi.y, c.y)};
}

OccupancyGrid::OccupancyGrid(const OccupancyGridParams& params)
    : params_(params),
      hit_(logit(params.hit_probability)),
      miss_(logit(params.miss_probability)),
      min_(logit(params.clamp_min)),
      max_(logit(params.clamp_max)) {}

CellIndex OccupancyGrid::cellOf(const Eigen::Vector2d& p) const {
  return {static_cast<std::int32_t>(std::floor(p.x() / params_.resolution)),
          static_cast<std::int32_t>(std::floor(p.y() / params_.resolution))};
}

Eigen::Vector2d OccupancyGrid::cellCentre(CellIndex c) const {
  return {(c.x + 0.5) * params_.resolution, (c.y + 0.5) * params_.resolution};
}

float* OccupancyGrid::cell(CellIndex c) {
  auto& tile = tiles_[tileKey(c, kTileBits)];
  if (!tile) tile = std::make_unique<Tile>();
  return &tile->log_odds[slotOf(c, kTileSide)];
}

const float* OccupancyGrid::findCell(CellIndex c) const {
  const auto it = tiles_.find(tileKey(c, kTileBits));
  return it == tiles_.end() ? nullptr : &it->second->log_odds[slotOf(c, kTileSide)];
}

float OccupancyGrid::logOdds(CellIndex c) const {
  const float* v = findCell(c);
  return v ? *v : 0.0f;
}

void OccupancyGrid::setLogOdds(CellIndex c, float value) {
  *cell(c) = value;
  bounds_.include(c);
  changed_.include(c);
}

double OccupancyGrid::probability(CellIndex c) const { return probabilityOf(logOdds(c)); }

std::int8_t OccupancyGrid::rosValue(CellIndex c) const {
  const float* v = findCell(c);
  if (v == nullptr || *v == 0.0f) return kRosUnknown;
  return static_cast<std::int8_t>(std::lround(probabilityOf(*v) * kRosOccupied));
}

void OccupancyGrid::update(CellIndex c, float delta) {
  float* v = cell(c);
  *v = std::clamp(*v + delta, min_, max_);
  bounds_.include(c);
  changed_.include(c);
}

void OccupancyGrid::traceFree(const Eigen::Vector2d& from, const Eigen::Vector2d& to, bool mark_end_occupied) {
  // Amanatides-Woo grid traversal: every cell the segment crosses, once.
  CellIndex c = cellOf(from);
  const CellIndex end = cellOf(to);
  const Eigen::Vector2d d = to - from;
  const int step_x = d.x() > 0 ? 1 : -1, step_y = d.y() > 0 ? 1 : -1;
  const double r = params_.resolution;
  const double inf = std::numeric_limits<double>::infinity();
  const double delta_x = d.x() != 0 ? std::abs(r / d.x()) : inf;
  const double delta_y = d.y() != 0 ? std::abs(r / d.y()) : inf;
  double next_x = d.x() != 0 ? ((c.x + (step_x > 0 ? 1 : 0)) * r - from.x()) / d.x() : inf;
  double next_y = d.y() != 0 ? ((c.y + (step_y > 0 ? 1 : 0)) * r - from.y()) / d.y() : inf;
  const std::int64_t max_steps = std::abs(static_cast<std::int64_t>(end.x) - c.x) + std::abs(static_cast<std::int64_t>(end.y) - c.y);
  for (std::int64_t s = 0; s < max_steps && !(c == end); ++s) {
    update(c, miss_);
    if (next_x < next_y) {
      c.x += step_x;
      next_x += delta_x;
    } else {
      c.y += step_y;
      next_y += delta_y;
    }
  }
  if (mark_end_occupied) update(end, hit_);
}

void OccupancyGrid::integrate(const Scan& scan, const SensorInfo& sensor, const std::vector<std::uint8_t>& labels) {
  const Eigen::Vector2d origin = sensorOrigin(scan.pose, sensor.mount);
  for (std::size_t i = 0; i < scan.size(); ++i) {
    const auto code = labels.empty() ? (scan.hasReturn(i) ? PointCode::kValid : PointCode::kNoReturn)
                                     : static_cast<PointCode>(labels[i]);
    if (code == PointCode::kValid) {
      traceFree(origin, beamToWorld(scan, sensor, i), true);
    } else if (code == PointCode::kNoReturn && params_.clear_on_no_return) {
      const double phi = beamWorldAngle(scan, sensor, i);
      traceFree(origin, origin + params_.no_return_clear_range * Eigen::Vector2d(std::cos(phi), std::sin(phi)), false);
    }
  }
  ++scans_;
}

CellBox OccupancyGrid::takeChanged() {
  const CellBox out = changed_;
  changed_ = CellBox{};
  return out;
}

std::size_t OccupancyGrid::memoryBytes() const {
  return tiles_.size() * (sizeof(Tile) + kTileSide * kTileSide * sizeof(float) + 3 * sizeof(void*));
}

}  // namespace scanfilter
