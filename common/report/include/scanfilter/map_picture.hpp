#pragma once
#include <string>
#include <vector>

#include "scanfilter/png_image.hpp"

namespace scanfilter {

// Occupancy maps framed for people: each of `panels` is a map drawn one
// pixel a cell (map_server's grey levels: black occupied, white free, grey
// unknown), all of one size and `cell_size` metres a cell; they are set side
// by side (to compare maps of one place). Each cell becomes a square of
// pixels so that a room fills the picture, under `title`, above a legend of
// the grey levels and a scale bar of a round length.
PngImage mapPicture(const std::vector<PngImage>& panels, double cell_size, const std::string& title);

}  // namespace scanfilter
