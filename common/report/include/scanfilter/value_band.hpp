#pragma once
#include <cstddef>
#include <span>

namespace scanfilter {

// The band a value falls in between ascending edges: 0 below edges[0], k in
// [edges[k-1], edges[k]), edges.size() at or above the last edge. A report's
// bands (range, incidence) are edges and one function, so every table bands
// the same way.
inline std::size_t bandOf(double value, std::span<const double> edges) {
  std::size_t band = 0;
  while (band < edges.size() && value >= edges[band]) ++band;
  return band;
}

}  // namespace scanfilter
