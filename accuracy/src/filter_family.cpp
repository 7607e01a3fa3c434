#include "scanfilter/accuracy/filter_family.hpp"

#include <algorithm>
#include <random>
#include <sstream>

namespace scanfilter::accuracy {

namespace {
constexpr std::uint32_t kSweepOrderSeed = 1;  // fixes which grid points a budget reaches
}  // namespace

std::vector<ParamValues> sweepPoints(const FilterFamily& family, std::size_t budget) {
  // Every grid point, in mixed-radix order: point 0 takes every default.
  std::vector<ParamValues> grid(1);
  for (const auto& axis : family.axes) {
    std::vector<ParamValues> next;
    for (const auto& partial : grid)
      for (double value : axis.values) {
        ParamValues point = partial;
        point[axis.name] = value;
        next.push_back(std::move(point));
      }
    grid = std::move(next);
  }
  // The mixed-radix order puts the defaults first in every axis, so point 0
  // is the shipped filter; the rest are shuffled so a budget samples them all.
  std::mt19937 rng(kSweepOrderSeed);
  std::shuffle(grid.begin() + 1, grid.end(), rng);
  if (grid.size() > budget) grid.resize(std::max<std::size_t>(budget, 1));
  return grid;
}

std::string describe(const FilterFamily& family, const ParamValues& values) {
  std::ostringstream out;
  for (const auto& axis : family.axes) {
    if (axis.values.size() < 2) continue;
    if (out.tellp() > 0) out << " ";
    out << axis.name << "=" << values.at(axis.name);
  }
  return out.str();
}

}  // namespace scanfilter::accuracy
