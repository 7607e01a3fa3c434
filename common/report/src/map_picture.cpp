#include "scanfilter/map_picture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace scanfilter {

namespace {

// A small map (a room at 5 cm is 200 cells) is drawn this large at least;
// each cell at most this many pixels across, so a cell stays a visible square
// and a map already this large keeps one pixel a cell.
constexpr int kMinLongerSide = 800;
constexpr int kMaxPixelsPerCell = 8;
constexpr int kTextScale = 2;
constexpr int kMargin = 10;
// A band holds one line of text (the title, the legend, the scale bar's
// label) and its margins; the picture has three besides the maps.
const int kBandHeight = PngImage::glyphHeight(kTextScale) + 2 * kMargin;
constexpr int kBands = 3;
constexpr int kScaleBarThickness = 6;
// The scale bar's length: the longest of these (metres) that fits in a
// quarter of the picture.
constexpr std::array kScaleBarLengths = {0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0};
constexpr double kScaleBarShareOfWidth = 0.25;
// The frame is pale blue, so that the white swatch of free space shows on it.
constexpr Rgb kFrameColour = {215, 225, 240};
constexpr Rgb kTextColour = {0, 0, 0};

Rgb grey(std::uint8_t level) { return {level, level, level}; }

const std::vector<std::pair<Rgb, std::string>>& legendEntries() {
  static const std::vector<std::pair<Rgb, std::string>> entries = {{grey(MapServerGrey::kOccupied), "OCCUPIED"},
                                                                    {grey(MapServerGrey::kFree), "FREE"},
                                                                    {grey(MapServerGrey::kUnknown), "UNKNOWN"}};
  return entries;
}

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

// The bar and its label, centred in the band whose top is `band_top`.
void drawScaleBar(PngImage& image, int band_top, double pixels_per_metre) {
  const double fits = kScaleBarShareOfWidth * image.width() / pixels_per_metre;
  double length = kScaleBarLengths.front();
  for (double candidate : kScaleBarLengths)
    if (candidate <= fits) length = candidate;
  const int pixels = std::max(1, static_cast<int>(std::lround(length * pixels_per_metre)));
  const int bar_top = band_top + (kBandHeight - kScaleBarThickness) / 2;
  image.fillRect(kMargin, bar_top, kMargin + pixels - 1, bar_top + kScaleBarThickness - 1, kTextColour);
  image.text(2 * kMargin + pixels, band_top + kMargin, metres(length), kTextColour, kTextScale);
}

// Wide enough for the maps, the title, the legend and the longest scale
// bar's label however narrow the maps.
int pictureWidth(int maps_width, const std::string& title) {
  const int title_width = static_cast<int>(title.size()) * PngImage::glyphAdvance(kTextScale);
  const int legend_width = PngImage::legendWidth(legendEntries(), kTextScale);
  return std::max({maps_width, title_width, legend_width}) + 2 * kMargin;
}

}  // namespace

PngImage mapPicture(const std::vector<PngImage>& panels, double cell_size, const std::string& title) {
  if (panels.empty()) throw std::invalid_argument("mapPicture: no map to draw");
  if (!(cell_size > 0.0 && std::isfinite(cell_size)))
    throw std::invalid_argument("mapPicture: cell size " + std::to_string(cell_size) + " m is not a positive number");
  int longer = 1, height = 1;
  for (const PngImage& cells : panels) longer = std::max({longer, cells.width(), cells.height()});
  const int factor = std::clamp(kMinLongerSide / longer, 1, kMaxPixelsPerCell);
  std::vector<PngImage> maps;
  int maps_width = -kMargin;  // a margin between two maps, none after the last
  for (const PngImage& cells : panels) {
    maps.push_back(scaledUp(cells, factor));
    maps_width += maps.back().width() + kMargin;
    height = std::max(height, maps.back().height());
  }
  PngImage image(pictureWidth(maps_width, title), height + kBands * kBandHeight, kFrameColour);
  image.text(kMargin, kMargin, title, kTextColour, kTextScale);
  int x = kMargin;
  for (const PngImage& map : maps) {
    image.paste(map, x, kBandHeight);
    x += map.width() + kMargin;
  }
  const int legend_band_top = kBandHeight + height;
  image.legend(kMargin, legend_band_top + kMargin, legendEntries(), kTextColour, kTextScale);
  drawScaleBar(image, legend_band_top + kBandHeight, factor / cell_size);
  return image;
}

}  // namespace scanfilter
