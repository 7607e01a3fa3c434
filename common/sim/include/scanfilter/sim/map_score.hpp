#pragma once
#include "scanfilter/occupancy_grid.hpp"
#include "scanfilter/sim/scene.hpp"

namespace scanfilter::sim {

// How well an occupancy map matches a scene's floor plan.
struct MapScore {
  std::size_t occupied = 0;          // cells above occupied_threshold
  std::size_t occupied_on_surface = 0;  // of those, within one cell of a true surface
  std::size_t surface_samples = 0;   // points sampled along every true surface
  std::size_t surface_covered = 0;   // of those, with an occupied cell within one cell
  double precision() const { return occupied ? static_cast<double>(occupied_on_surface) / static_cast<double>(occupied) : 0.0; }
  double recall() const { return surface_samples ? static_cast<double>(surface_covered) / static_cast<double>(surface_samples) : 0.0; }
};

MapScore scoreMap(const OccupancyGrid& grid, const Scene& scene);

}  // namespace scanfilter::sim
