#include "scanfilter/sim/map_score.hpp"

#include <cmath>
#include <numbers>

#include "scanfilter/sim/ray_caster.hpp"

namespace scanfilter::sim {

namespace {
// A cell "lies on" a surface when its centre is within one cell (and the
// half-diagonal of its own) of it.
constexpr double kOnSurfaceCells = 1.0 + 0.7072;
}  // namespace

MapScore scoreMap(const OccupancyGrid& grid, const Scene& scene) {
  MapScore score;
  const RayCaster caster(scene);
  const double r = grid.params().resolution;
  const CellBox box = grid.bounds();
  const auto occupied = [&](CellIndex c) { return grid.probability(c) > grid.params().occupied_threshold; };
  for (std::int32_t y = box.lo.y; y <= box.hi.y; ++y)
    for (std::int32_t x = box.lo.x; x <= box.hi.x; ++x) {
      if (!occupied({x, y})) continue;
      ++score.occupied;
      score.occupied_on_surface += caster.distanceToSurface(grid.cellCentre({x, y})) <= kOnSurfaceCells * r;
    }
  const auto sample = [&](const Eigen::Vector2d& p) {
    ++score.surface_samples;
    const CellIndex c = grid.cellOf(p);
    bool hit = false;
    for (int dy = -1; dy <= 1 && !hit; ++dy)
      for (int dx = -1; dx <= 1 && !hit; ++dx) hit = occupied({c.x + dx, c.y + dy});
    score.surface_covered += hit;
  };
  for (const Segment& s : scene.segments) {
    const int n = std::max(1, static_cast<int>((s.b - s.a).norm() / r));
    for (int k = 0; k <= n; ++k) sample(s.a + (s.b - s.a) * (static_cast<double>(k) / n));
  }
  for (const Leg& leg : scene.legs) sample(leg.centre);
  return score;
}

}  // namespace scanfilter::sim
