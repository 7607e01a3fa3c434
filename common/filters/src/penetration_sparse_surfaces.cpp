// PenetrationFilter, part 3 of 4: the sparse surfaces (Beyond the paper 29).
// Panes and glossy walls return a beam only now and then, so the cache holds
// them one return at a time; lines through such cells are found and handed
// to the surface memory, without the cells that a cached frame saw beyond a
// surface (a mirror's reflections line up too).
#include <algorithm>
#include <unordered_map>
#include <vector>

#include "scanfilter/cell_key.hpp"
#include "scanfilter/penetration_filter.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/sparse_surfaces.hpp"

namespace scanfilter {

void PenetrationFilter::rememberSparseSurfaces(const Eigen::Vector2d& origin, Stamp stamp) {
  const SparseSurfaceParams& sparse = params_.surface_memory.sparse_surfaces;
  std::vector<CellMean> cells = cellsInReach(origin);
  std::vector<StraightSegment> found = sparseSurfaces(cells, grid_.cellSize(), sparse);
  if (found.empty()) return;
  // A return seen beyond a surface is no evidence of another: a mirror's or
  // a pane's reflections line up too, as the image of the wall they came
  // from. So the surfaces found, at any angle, are remembered in a copy of
  // the memory, which then serves to find the cells on them that a cached
  // frame saw beyond a surface; the search runs again without those (what
  // it then finds is not asked again).
  SurfaceMemory surfaces = memory_;
  surfaces.rememberSegments(found, origin, stamp, 0.0);
  if (dropCellsSeenBeyond(surfaces, found, stamp, cells)) found = sparseSurfaces(cells, grid_.cellSize(), sparse);
  memory_.rememberSegments(found, origin, stamp, sparse.min_beam_surface_angle_deg);
}

std::vector<CellMean> PenetrationFilter::cellsInReach(const Eigen::Vector2d& origin) const {
  Eigen::AlignedBox2d box = returnBounds(points_);
  box.extend(origin);
  // The noise step 2 measures (Beyond the paper 33), at the cell's range
  // from this frame's sensor: the cells in reach were seen from near here.
  const RangeNoiseModel noise = evidence_radius_.noise();
  std::vector<CellMean> cells;
  grid_.forEachCountedCellIn(grid_.cellOf(box.min()), grid_.cellOf(box.max()),
                             [&](CellIndex c, int count, const Eigen::Vector2d& at) {
                               cells.push_back({c, at, count <= params_.obstacle_threshold,
                                                noise.sigmaAt((at - origin).norm())});
                             });
  return cells;
}

bool PenetrationFilter::dropCellsSeenBeyond(const SurfaceMemory& surfaces, std::span<const StraightSegment> found,
                                            Stamp stamp, std::vector<CellMean>& cells) const {
  // Only the sparse cells on the surfaces found are asked: the others could
  // change what is found only as neighbours, and asking every cached run
  // about every sparse cell cost as much as the search itself.
  // As far off a found surface as its cells may lie: the deviation limit
  // and a cell, or as far as the noise may widen that limit (42).
  const SparseSurfaceParams& sparse = params_.surface_memory.sparse_surfaces;
  double tolerance = sparse.max_deviation + grid_.cellSize();
  if (sparse.max_deviation_noise_sigmas > 0.0) tolerance = std::max(tolerance, sparse.max_deviation_ceiling);
  const auto onAFoundSurface = [&](const Eigen::Vector2d& p) {
    return std::any_of(found.begin(), found.end(), [&](const StraightSegment& s) {
      return distanceToSegment(p, s.a, s.b) <= tolerance;
    });
  };
  std::unordered_map<std::uint64_t, std::size_t> asked;  // cell key -> index in `cells`
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (cells[i].sparse && onAFoundSurface(cells[i].at)) asked.emplace(cellKey(cells[i].cell.x, cells[i].cell.y), i);
  std::vector<bool> seen_beyond(cells.size(), false);
  bool any = false;
  for (const CachedFrame& frame : cache_) {
    for (const CellRun& run : frame.votes) {
      const auto it = asked.find(cellKey(run.cell.x, run.cell.y));
      if (it == asked.end() || seen_beyond[it->second]) continue;
      seen_beyond[it->second] = surfaces.liesBeyondASurface(frame.placed_origin, cells[it->second].at, stamp);
      any = any || seen_beyond[it->second];
    }
  }
  if (!any) return false;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (!seen_beyond[i]) cells[kept++] = cells[i];
  cells.resize(kept);
  return true;
}

}  // namespace scanfilter
