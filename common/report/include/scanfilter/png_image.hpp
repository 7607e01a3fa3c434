#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace scanfilter {

using Rgb = std::array<std::uint8_t, 3>;

// An RGB raster written as PNG, with the few drawing primitives plots need.
class PngImage {
 public:
  PngImage(int width, int height, Rgb background = {255, 255, 255});

  int width() const { return width_; }
  int height() const { return height_; }
  void set(int x, int y, Rgb colour);
  Rgb get(int x, int y) const;
  void fillRect(int x0, int y0, int x1, int y1, Rgb colour);
  void disc(int cx, int cy, int radius, Rgb colour);
  void line(int x0, int y0, int x1, int y1, Rgb colour);
  // Upper-case text in a 5x7 pixel font, `scale` pixels per font pixel.
  // Each character takes glyphAdvance(scale) pixels across.
  static int glyphAdvance(int scale);
  static int glyphHeight(int scale);
  void text(int x, int y, const std::string& s, Rgb colour, int scale = 2);
  // A row of colour swatches, each followed by its name.
  void legend(int x, int y, const std::vector<std::pair<Rgb, std::string>>& entries, Rgb text_colour, int scale = 2);
  // How wide legend() draws those entries, in pixels.
  static int legendWidth(const std::vector<std::pair<Rgb, std::string>>& entries, int scale = 2);
  // Pastes another image with its top-left corner at (x, y).
  void paste(const PngImage& other, int x, int y);

  void save(const std::string& path) const;  // throws std::runtime_error

 private:
  int width_;
  int height_;
  std::vector<std::uint8_t> pixels_;
};

}  // namespace scanfilter
