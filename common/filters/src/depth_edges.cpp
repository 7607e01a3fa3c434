#include "scanfilter/depth_edges.hpp"

#include <algorithm>
#include <limits>

namespace scanfilter {

namespace {

// Up to this many beams a window's maximum is cheaper taken beam by beam
// than by the blocks below (step 2's free-space candidates use 3). Measured
// at 3,600 beams: 11.9 against 14.1 µs a scan for windows of 3, 13.9
// against 14.8 for 5, 15.9 against 13.7 for 7 (the blocks cost the same at
// any width).
constexpr std::size_t kDirectWindowMax = 5;

// The maximum of `range` within `half_width` of each beam, beam by beam.
std::vector<double> farthestTestingEach(const std::vector<double>& range, std::size_t half_width) {
  const std::size_t n = range.size();
  std::vector<double> farthest(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i > half_width ? i - half_width : 0;
    const std::size_t hi = std::min(n - 1, i + half_width);
    farthest[i] = *std::max_element(range.begin() + static_cast<std::ptrdiff_t>(lo),
                                    range.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
  }
  return farthest;
}

// For each beam k, the largest of `range` from the start of k's block of
// `block` beams up to k (from_start) and from k to the block's end (to_end).
void blockRunningMaxima(const std::vector<double>& range, std::size_t block, std::vector<double>& from_start,
                        std::vector<double>& to_end) {
  const std::size_t n = range.size();
  from_start.resize(n);
  to_end.resize(n);
  for (std::size_t start = 0; start < n; start += block) {
    const std::size_t end = std::min(n, start + block);
    from_start[start] = range[start];
    for (std::size_t k = start + 1; k < end; ++k) from_start[k] = std::max(from_start[k - 1], range[k]);
    to_end[end - 1] = range[end - 1];
    for (std::size_t k = end - 1; k-- > start;) to_end[k] = std::max(to_end[k + 1], range[k]);
  }
}

// The maximum of `range` within `half_width` of each beam in O(n) whatever
// the width: the van Herk / Gil-Werman running maximum over blocks of one
// window's length.
std::vector<double> farthestByBlocks(const std::vector<double>& range, std::size_t half_width) {
  const std::size_t n = range.size();
  const std::size_t window = 2 * half_width + 1;
  std::vector<double> from_start, to_end;
  blockRunningMaxima(range, window, from_start, to_end);
  // A window [lo, hi] is at most one block long. Across two blocks its
  // maximum is to_end at lo (to lo's block end) with from_start at hi (from
  // hi's block start). Within one block it starts at the block's start (a
  // whole window, or one cut by the scan's start: from_start at hi) or ends
  // at the scan's end (cut there: to_end at lo).
  std::vector<double> farthest(n);
  std::size_t lo_in_block = 0;  // lo % window, kept without dividing
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t lo = i > half_width ? i - half_width : 0;
    const std::size_t hi = std::min(n - 1, i + half_width);
    if (i > half_width && ++lo_in_block == window) lo_in_block = 0;
    if (lo_in_block + (hi - lo) >= window) farthest[i] = std::max(to_end[lo], from_start[hi]);
    else farthest[i] = lo_in_block == 0 ? from_start[hi] : to_end[lo];
  }
  return farthest;
}

// The farthest background range within `half_width` beams of each beam
// (-inf where there is none). The test "some background return in the
// window is farther than x" is then one comparison per beam, with the answer
// of testing each return in the window (a maximum is exact: no rounding).
std::vector<double> farthestBackgroundAround(const Scan& scan, const BeamMask& background,
                                             std::size_t half_width) {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  std::vector<double> range(scan.size(), kNone);
  for (std::size_t k = 0; k < scan.size(); ++k)
    if (background[k] && scan.hasReturn(k)) range[k] = scan.ranges[k];
  return 2 * half_width + 1 <= kDirectWindowMax ? farthestTestingEach(range, half_width)
                                                : farthestByBlocks(range, half_width);
}

}  // namespace

BeamMask nearSideOfDepthEdge(const Scan& scan, const BeamMask& background, int half_width_beams, double depth_step) {
  BeamMask edge(scan.size());
  if (half_width_beams <= 0 || scan.size() == 0) return edge;
  const std::vector<double> farthest =
      farthestBackgroundAround(scan, background, static_cast<std::size_t>(half_width_beams));
  for (std::size_t i = 0; i < scan.size(); ++i)
    edge.set(i, scan.hasReturn(i) && farthest[i] > scan.ranges[i] + depth_step);
  return edge;
}

}  // namespace scanfilter
