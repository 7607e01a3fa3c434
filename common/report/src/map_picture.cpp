#include "scanfilter/map_picture.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

namespace scanfilter {

namespace {

// A small map (a room at 5 cm is 200 cells) is drawn this large at least;
// each cell at most this many pixels across, so a cell stays a visible square
// and a map already this large keeps one pixel a cell.
constexpr int kMinLongerSide = 800;
constexpr int kMaxPixelsPerCell = 8;
constexpr int kTextScale = 2;
constexpr int kMargin = 10;
constexpr int kBandHeight = 7 * kTextScale + 2 * kMargin;  // one line of text and its margins
constexpr int kScaleBarThickness = 6;
// The scale bar's length: the longest of these (metres) that fits in a
// quarter of the picture.
constexpr std::array kScaleBarLengths = {0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0};
constexpr double kScaleBarShareOfWidth = 0.25;
// The frame is pale blue, so that the white swatch of free space shows on it.
constexpr Rgb kFrameColour = {215, 225, 240};
constexpr Rgb kTextColour = {0, 0, 0};
// map_server's trinary grey levels, as the map's raster draws them.
constexpr Rgb kOccupiedColour = {0, 0, 0};
constexpr Rgb kFreeColour = {254, 254, 254};
constexpr Rgb kUnknownColour = {205, 205, 205};

PngImage scaledUp(const PngImage& cells, int factor) {
  PngImage out(cells.width() * factor, cells.height() * factor);
  for (int y = 0; y < cells.height(); ++y)
    for (int x = 0; x < cells.width(); ++x)
      out.fillRect(x * factor, y * factor, (x + 1) * factor - 1, (y + 1) * factor - 1, cells.get(x, y));
  return out;
}

std::string metres(double m) {
  char text[32];
  std::snprintf(text, sizeof text, "%g M", m);
  return text;
}

void drawScaleBar(PngImage& image, int x, int y, double pixels_per_metre) {
  const double fits = kScaleBarShareOfWidth * image.width() / pixels_per_metre;
  double length = kScaleBarLengths.front();
  for (double candidate : kScaleBarLengths)
    if (candidate <= fits) length = candidate;
  const int pixels = std::max(1, static_cast<int>(length * pixels_per_metre + 0.5));
  image.fillRect(x, y, x + pixels - 1, y + kScaleBarThickness - 1, kTextColour);
  image.text(x + pixels + kMargin, y - (7 * kTextScale - kScaleBarThickness) / 2, metres(length), kTextColour,
             kTextScale);
}

}  // namespace

PngImage mapPicture(const std::vector<PngImage>& panels, double cell_size, const std::string& title) {
  int longer = 1, height = 1;
  for (const PngImage& cells : panels) longer = std::max({longer, cells.width(), cells.height()});
  const int factor = std::clamp(kMinLongerSide / longer, 1, kMaxPixelsPerCell);
  std::vector<PngImage> maps;
  int maps_width = 0;
  for (const PngImage& cells : panels) {
    maps.push_back(scaledUp(cells, factor));
    maps_width += maps.back().width() + kMargin;
    height = std::max(height, maps.back().height());
  }
  // Wide enough for the title and the legend however narrow the maps.
  const int min_width = 2 * kMargin + static_cast<int>(title.size()) * PngImage::glyphAdvance(kTextScale);
  PngImage image(std::max(maps_width + kMargin, min_width), height + 3 * kBandHeight, kFrameColour);
  image.text(kMargin, kMargin, title, kTextColour, kTextScale);
  int x = kMargin;
  for (const PngImage& map : maps) {
    image.paste(map, x, kBandHeight);
    x += map.width() + kMargin;
  }
  const int below = kBandHeight + height + kMargin;
  image.legend(kMargin, below, {{kOccupiedColour, "OCCUPIED"}, {kFreeColour, "FREE"}, {kUnknownColour, "UNKNOWN"}},
               kTextColour, kTextScale);
  drawScaleBar(image, kMargin, below + kBandHeight + (7 * kTextScale - kScaleBarThickness) / 2,
               factor / cell_size);
  return image;
}

}  // namespace scanfilter
