#include "scanfilter/depth_edges.hpp"

#include <algorithm>

namespace scanfilter {

std::vector<bool> nearSideOfDepthEdge(const Scan& scan, const std::vector<bool>& background, int half_width_beams,
                                      double depth_step) {
  const auto n = static_cast<std::ptrdiff_t>(scan.size());
  std::vector<bool> edge(scan.size(), false);
  if (half_width_beams <= 0) return edge;
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    if (!scan.hasReturn(static_cast<std::size_t>(i))) continue;
    const double farther = scan.ranges[static_cast<std::size_t>(i)] + depth_step;
    const std::ptrdiff_t lo = std::max<std::ptrdiff_t>(0, i - half_width_beams);
    const std::ptrdiff_t hi = std::min<std::ptrdiff_t>(n - 1, i + half_width_beams);
    for (std::ptrdiff_t j = lo; j <= hi && !edge[static_cast<std::size_t>(i)]; ++j) {
      const auto k = static_cast<std::size_t>(j);
      edge[static_cast<std::size_t>(i)] = background[k] && scan.ranges[k] > farther;
    }
  }
  return edge;
}

}  // namespace scanfilter
