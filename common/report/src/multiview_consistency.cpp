#include "scanfilter/multiview_consistency.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <unordered_map>

#include "scanfilter/cell_key.hpp"
#include "scanfilter/scan_geometry.hpp"

namespace scanfilter {

namespace {

// A cell of a square grid: of returns, or of viewpoints.
struct GridIndex {
  std::int32_t x = 0;
  std::int32_t y = 0;
  bool operator==(const GridIndex&) const = default;
};

GridIndex gridIndex(const Eigen::Vector2d& p, double cell) {
  return {static_cast<std::int32_t>(std::floor(p.x() / cell)), static_cast<std::int32_t>(std::floor(p.y() / cell))};
}

std::uint64_t packed(GridIndex c) { return cellKey(c.x, c.y); }

int chebyshev(GridIndex a, GridIndex b) { return std::max(std::abs(a.x - b.x), std::abs(a.y - b.y)); }

void validate(const MultiviewParams& p) {
  if (!(p.cell_size > 0.0) || !(p.position_cell > 0.0) || p.neighbourhood_cells < 0 || p.adjacent_positions < 0 ||
      p.min_viewpoints < 1)
    throw std::invalid_argument(
        "multiview consistency: cell sizes must be > 0, neighbourhood and adjacency >= 0, min_viewpoints >= 1");
}

// The distinct viewpoints that hit each cell of returns. A cell keeps at most
// `capacity` of them: with min_viewpoints + (2a + 1)^2 distinct viewpoints,
// at most (2a + 1)^2 can be adjacent to any one return's viewpoint, so the
// cell alone already makes every return near it re-observed; more would only
// cost time in the cells seen from everywhere.
class ViewpointGrid {
 public:
  explicit ViewpointGrid(const MultiviewParams& p)
      : capacity_(static_cast<std::size_t>(p.min_viewpoints) +
                  static_cast<std::size_t>((2 * p.adjacent_positions + 1) * (2 * p.adjacent_positions + 1))) {}

  void add(GridIndex cell, GridIndex viewpoint) {
    auto& seen = cells_[packed(cell)];
    if (seen.size() >= capacity_ || std::find(seen.begin(), seen.end(), viewpoint) != seen.end()) return;
    seen.push_back(viewpoint);
  }

  const std::vector<GridIndex>* find(GridIndex cell) const {
    const auto it = cells_.find(packed(cell));
    return it == cells_.end() ? nullptr : &it->second;
  }

 private:
  std::size_t capacity_;
  std::unordered_map<std::uint64_t, std::vector<GridIndex>> cells_;
};

// Whether the cells around `cell` were hit from min_viewpoints distinct
// viewpoints farther than adjacent_positions from `own`.
bool seenFromElsewhere(const ViewpointGrid& grid, GridIndex cell, GridIndex own, const MultiviewParams& p,
                       std::vector<GridIndex>& found) {
  found.clear();
  const int n = p.neighbourhood_cells;
  for (int dy = -n; dy <= n; ++dy) {
    for (int dx = -n; dx <= n; ++dx) {
      const auto* seen = grid.find({cell.x + dx, cell.y + dy});
      if (!seen) continue;
      for (const GridIndex& v : *seen) {
        if (chebyshev(v, own) <= p.adjacent_positions || std::find(found.begin(), found.end(), v) != found.end())
          continue;
        found.push_back(v);
        if (found.size() >= static_cast<std::size_t>(p.min_viewpoints)) return true;
      }
    }
  }
  return false;
}

}  // namespace

ReobservationMap findReobservedReturns(std::span<const Scan> scans, const SensorInfo& sensor,
                                       const MultiviewParams& params) {
  validate(params);
  BeamDirectionTable directions;
  std::vector<Eigen::Vector2d> points;
  std::vector<GridIndex> viewpoints(scans.size());

  // Every return, with the viewpoint it was seen from.
  ViewpointGrid grid(params);
  for (std::size_t s = 0; s < scans.size(); ++s) {
    viewpoints[s] = gridIndex(sensorOrigin(scans[s].pose, sensor.mount), params.position_cell);
    worldPoints(scans[s], sensor, directions, points);
    for (std::size_t i = 0; i < points.size(); ++i)
      if (scans[s].hasReturn(i)) grid.add(gridIndex(points[i], params.cell_size), viewpoints[s]);
  }

  ReobservationMap out(scans.size());
  std::vector<GridIndex> found;
  for (std::size_t s = 0; s < scans.size(); ++s) {
    worldPoints(scans[s], sensor, directions, points);
    out[s].assign(points.size(), Reobservation::kNoReturn);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!scans[s].hasReturn(i)) continue;
      out[s][i] = seenFromElsewhere(grid, gridIndex(points[i], params.cell_size), viewpoints[s], params, found)
                      ? Reobservation::kReobserved
                      : Reobservation::kNotReobserved;
    }
  }
  return out;
}

}  // namespace scanfilter
