#pragma once
// A filter with the parameter grid its tuning sweep draws from. The first
// value of every axis is the filter's published default, so grid point 0 is
// the filter as shipped.
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "scanfilter/scan_filter.hpp"

namespace scanfilter::accuracy {

struct SweepAxis {
  std::string name;
  std::vector<double> values;  // values[0]: the default
};

using ParamValues = std::map<std::string, double>;
using FilterBuilder = std::function<std::unique_ptr<ScanFilter>(const ParamValues&, const SensorInfo&)>;

struct FilterFamily {
  std::string name;    // as the table and plots show it
  std::string source;  // where the method and its defaults come from
  std::vector<SweepAxis> axes;
  FilterBuilder build;
};

// The grid points a sweep of `budget` evaluations tries: the default first,
// then the rest of the grid in a fixed pseudo-random order (all of it when it
// fits the budget). Same family and budget, same points.
std::vector<ParamValues> sweepPoints(const FilterFamily& family, std::size_t budget);

// "alpha=0.6 theta_k=70" (axes with one value left out).
std::string describe(const FilterFamily& family, const ParamValues& values);

}  // namespace scanfilter::accuracy
