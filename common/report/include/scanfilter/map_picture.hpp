#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scanfilter/png_image.hpp"

namespace scanfilter {

// map_server's trinary grey levels (ROS map_server, mode: trinary): what an
// occupancy map's PGM holds and its picture shows.
struct MapServerGrey {
  static constexpr std::uint8_t kOccupied = 0;
  static constexpr std::uint8_t kFree = 254;
  static constexpr std::uint8_t kUnknown = 205;
};

// Occupancy maps framed for people: each of `panels` is a map drawn one
// pixel a cell in MapServerGrey levels, all of one size and `cell_size`
// metres a cell; they are set side by side (to compare maps of one place).
// Each cell becomes a square of pixels so that a room fills the picture,
// under `title`, above a legend of the grey levels and a scale bar of a
// round length. Throws std::invalid_argument for no panels or a cell size
// that is not a positive number.
PngImage mapPicture(const std::vector<PngImage>& panels, double cell_size, const std::string& title);

}  // namespace scanfilter
