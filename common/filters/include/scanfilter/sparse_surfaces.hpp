#pragma once
#include <span>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/straight_segments.hpp"

namespace scanfilter {

// How a straight surface is found among cells that each hold only a few
// returns (docs/accuracy.md, Beyond the paper 29). The counts are for the
// sensor's angular step (FilterConfig::resolve scales them).
struct SparseSurfaceParams {
  bool enabled = true;
  double min_beam_surface_angle_deg = 30.0;  // the beam to a surface's middle meets it at this or more
  double neighbour_radius = 0.25;  // m, the cells within this of a cell give its local line
  int min_neighbours = 4;          // cells (itself included) a local line needs
  double max_thickness = 0.015;    // m, σ of those cells across their line: thicker is no line
  double max_angle_deg = 10.0;     // degrees: neighbouring local lines this near in direction ...
  double max_gap = 0.30;           // m, ... and this near each other are one surface
  double max_deviation = 0.03;     // m, every cell of a surface lies this near its fitted line
  int min_cells = 6;               // sparse cells a surface needs
  double min_length = 0.30;        // m a surface needs
};

// A cell of the cache as the mean of its returns, and whether it holds too
// few of them to be an obstacle on its own.
struct CellMean {
  Eigen::Vector2d at;
  bool sparse = false;
};

// The straight surfaces whose sparse cells line up: a pane or a mirror
// returns a beam only now and then (near its normal, or a few per cent of
// the beams elsewhere), so over the cache's frames its returns scatter one
// or two to a cell along a line, below obs_th. Every cell (an obstacle too)
// counts as a neighbour; only sparse cells make a surface. Each sparse cell
// with enough neighbours lying thinly along a line gets that line's
// direction; such cells join when near each other, alike in direction and on
// each other's line; each group is fitted and split where its cells lie
// farther apart than max_gap (a doorway, not a pane's hole). `cells` must
// each lie in a distinct cell of width `cell_size`.
std::vector<StraightSegment> sparseSurfaces(std::span<const CellMean> cells, double cell_size,
                                            const SparseSurfaceParams& params);

}  // namespace scanfilter
