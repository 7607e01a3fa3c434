#pragma once
// Every valid return of a simulated run, by grid cell and time: how often a
// cell had been hit in a window before a given moment. The misdetected-error
// breakdown asks it whether a mirror or pane that step 2's cache did not
// hold had been seen at all, and how long before: what a memory of surfaces
// longer than T_max could find.
#include <algorithm>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/cell_key.hpp"
#include "scanfilter/floor_to_int.hpp"

namespace scanfilter::bench {

class SurfaceHistory {
 public:
  explicit SurfaceHistory(double cell_size) : cell_size_(cell_size) {}

  // Times must not decrease from one call to the next (scan order).
  void add(const Eigen::Vector2d& p, double t) {
    const Cell c = cellOf(p);
    times_[cellKey(c.x, c.y)].push_back(t);
  }

  // The most hits any cell within one cell of p took in [t - window, t).
  int mostHitsNear(const Eigen::Vector2d& p, double t, double window) const {
    const Cell c = cellOf(p);
    int most = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) most = std::max(most, hitsIn({c.x + dx, c.y + dy}, t - window, t));
    return most;
  }

 private:
  struct Cell {
    int x, y;
  };
  Cell cellOf(const Eigen::Vector2d& p) const { return {floorToInt(p.x() / cell_size_), floorToInt(p.y() / cell_size_)}; }
  int hitsIn(Cell c, double from, double to) const {
    const auto it = times_.find(cellKey(c.x, c.y));
    if (it == times_.end()) return 0;
    const std::vector<double>& times = it->second;  // sorted: added in scan order
    return static_cast<int>(std::lower_bound(times.begin(), times.end(), to) -
                            std::lower_bound(times.begin(), times.end(), from));
  }

  double cell_size_;
  std::unordered_map<std::uint64_t, std::vector<double>> times_;
};

}  // namespace scanfilter::bench
