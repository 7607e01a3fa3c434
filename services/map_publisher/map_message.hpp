#pragma once
#include <string>

#include "scanfilter/occupancy_grid.hpp"
#include "scanfilter_types.h"

namespace scanfilter::dds_io {

using MapMsg = nav_msgs::msg::dds_::OccupancyGrid_;
using MapUpdateMsg = map_msgs::msg::dds_::OccupancyGridUpdate_;

// The whole map as a ROS nav_msgs/OccupancyGrid: row-major from the
// lower-left cell, the map_server trinary values, stamped now.
void toMapMsg(const OccupancyGrid& grid, const std::string& frame_id, MapMsg& out);

// The changed rectangle as a map_msgs/OccupancyGridUpdate, in cells of the
// published map (its origin is the map's lower-left cell).
void toUpdateMsg(const OccupancyGrid& grid, const CellBox& changed, const std::string& frame_id, MapUpdateMsg& out);

}  // namespace scanfilter::dds_io
