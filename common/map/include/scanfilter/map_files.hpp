#pragma once
#include "scanfilter/png_image.hpp"
#include <string>

#include "scanfilter/occupancy_grid.hpp"

namespace scanfilter {

// Writes BASE.pgm + BASE.yaml (the ROS map_server format, trinary: 0
// occupied, 254 free, 205 unknown), BASE.png for people (mapPicture: large
// enough to see, with a legend and a scale bar), and BASE.logodds
// (the exact state, to continue from). Every file is written to a temporary
// name and renamed, so a crash never leaves a torn file. `note` (text, e.g.
// which scans the map holds) is stored in BASE.logodds after the cells: it
// is replaced in the same rename as the state it describes. `title` heads
// the picture (drawn in capitals; letters, digits and .,-:/%()=+_ only).
void saveMap(const OccupancyGrid& grid, const std::string& base, const std::string& note = {},
             const std::string& title = "OCCUPANCY MAP");

// The map one pixel a cell (map_server grey levels) over `box`, which may be
// larger than the grid's own bounds (to draw two maps on one frame); what
// mapPicture frames.
PngImage mapImage(const OccupancyGrid& grid, const CellBox& box);

// Restores the exact state saved in BASE.logodds into `grid` (same params);
// returns the note saved with it ("" if none).
std::string loadMapState(OccupancyGrid& grid, const std::string& base);

}  // namespace scanfilter
