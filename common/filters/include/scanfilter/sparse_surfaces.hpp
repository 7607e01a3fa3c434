#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/penetration_grid.hpp"
#include "scanfilter/straight_segments.hpp"

namespace scanfilter {

// How a straight surface is found among cells that each hold only a few
// returns (docs/beyond-the-paper.md, 29). config/filter.yaml gives
// min_neighbours and min_cells for a 1° step; FilterConfig::resolve scales
// them to the sensor's.
struct SparseSurfaceParams {
  bool enabled = true;
  double min_beam_surface_angle_deg = 30.0;  // the beam to a surface's middle meets it at this or more
  double neighbour_radius = 0.25;  // m, the cells within this of a cell give its local line
  int min_neighbours = 4;          // cells (itself included) a local line needs
  double max_thickness = 0.015;    // m, σ of those cells across their line: thicker is no line; a cell
                                   // lies on a line within twice this (as widened). Where the range noise
                                   // is larger (a ceiling below the limit widens nothing):
  double max_thickness_noise_sigmas = 1.5;  // this many σ of it at the cell's range, ...
  double max_thickness_ceiling = 0.03;      // m, ... up to this
  double max_angle_deg = 10.0;     // degrees: neighbouring local lines this near in direction ...
  double max_gap = 0.30;           // m, ... and this near each other are one surface
  double max_deviation = 0.03;     // m, every cell of a surface lies this near its fitted line; where the
                                   // range noise is larger:
  double max_deviation_noise_sigmas = 4.0;  // this many σ of it at the cell's range, ...
  double max_deviation_ceiling = 0.08;      // m, ... up to this
  int min_cells = 6;               // sparse cells a surface needs
  double min_length = 0.30;        // m a surface needs
};

// A cell of the cache: which one, the mean of its returns, whether it holds
// too few of them to be an obstacle on its own, and the range noise there.
struct CellMean {
  CellIndex cell;
  Eigen::Vector2d at;
  bool sparse = false;
  double range_noise = 0.0;  // m, σ of the sensor's range noise at the cell's range (0: not measured)
};

// Whether the search's limits widen with the range noise: it must then be
// measured.
inline bool followsRangeNoise(const SparseSurfaceParams& params) {
  return params.enabled && (params.max_thickness_noise_sigmas > 0.0 || params.max_deviation_noise_sigmas > 0.0);
}

// The straight surfaces whose sparse cells line up: a pane or a mirror
// returns a beam only now and then (near its normal, or a few per cent of
// the beams elsewhere), so over the cache's frames its returns scatter one
// or two to a cell along a line, below obs_th. Every cell (an obstacle too)
// counts as a neighbour; only sparse cells make a surface. Each sparse cell
// with enough neighbours lying thinly along a line through it gets that
// line's direction; two such cells join when within max_gap of each other
// (a pane's hole, not a doorway), alike in direction and each on the
// other's line; each group long, full and straight enough is fitted as one
// surface. A noisier sensor's returns of one line scatter farther across it,
// so a cell's thickness and deviation limits widen with its range noise
// (docs/beyond-the-paper.md, 42). Cells must be distinct; those with a
// non-finite mean are left out.
std::vector<StraightSegment> sparseSurfaces(std::span<const CellMean> cells, double cell_size,
                                            const SparseSurfaceParams& params);

}  // namespace scanfilter
