#include "scanfilter/reobservation_picture.hpp"

#include <array>

#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/world_viewport.hpp"

namespace scanfilter {

namespace {

constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kReobservedColour{120, 120, 120};
constexpr Rgb kNotReobservedColour{205, 205, 205};
constexpr Rgb kRemovedReobservedColour{225, 25, 25};
constexpr Rgb kRemovedNotReobservedColour{30, 80, 230};
constexpr Rgb kPathColour{40, 170, 70};
constexpr Rgb kTextColour{0, 0, 0};
constexpr int kMargin = 20;
constexpr int kTitleHeight = 30;
constexpr int kLegendHeight = 30;
constexpr int kTextScale = 2;

// What a return is in the picture; on a tie within a pixel the later kind
// wins, so a removed return beside a kept one still shows.
enum class Layer { kNotReobserved, kReobserved, kRemovedNotReobserved, kRemovedReobserved, kCount };
constexpr std::size_t kLayers = static_cast<std::size_t>(Layer::kCount);

Layer layerOf(Reobservation r, std::uint8_t label) {
  const bool reobserved = r == Reobservation::kReobserved;
  if (isRemovedCode(label)) return reobserved ? Layer::kRemovedReobserved : Layer::kRemovedNotReobserved;
  return reobserved ? Layer::kReobserved : Layer::kNotReobserved;
}

Rgb colourOf(Layer layer) {
  switch (layer) {
    case Layer::kReobserved: return kReobservedColour;
    case Layer::kRemovedNotReobserved: return kRemovedNotReobservedColour;
    case Layer::kRemovedReobserved: return kRemovedReobservedColour;
    default: return kNotReobservedColour;
  }
}

}  // namespace

PngImage drawRemovalsByReobservation(std::span<const Scan> scans, const SensorInfo& sensor,
                                     const ReobservationMap& reobservation,
                                     std::span<const std::vector<std::uint8_t>> labels, const std::string& title,
                                     int longer_side_pixels) {
  // Every return's world point and layer, and the box around them.
  struct Dot {
    Eigen::Vector2d p;
    Layer layer;
  };
  std::vector<Dot> dots;
  std::vector<Eigen::Vector2d> path, points;
  BeamDirectionTable directions;
  WorldBounds bounds;
  for (std::size_t s = 0; s < scans.size(); ++s) {
    path.push_back(sensorOrigin(scans[s].pose, sensor.mount));
    bounds.include(path.back());
    worldPoints(scans[s], sensor, directions, points);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (!scans[s].hasReturn(i)) continue;
      dots.push_back({points[i], layerOf(reobservation[s][i], labels[s][i])});
      bounds.include(points[i]);
    }
  }
  const WorldViewport view = bounds.viewport(longer_side_pixels);

  // Per pixel, how many returns of each kind fell in it: a pixel spans a few
  // centimetres, and a dense log puts hundreds of returns in a wall's pixel.
  const auto width = static_cast<std::size_t>(view.width());
  std::vector<std::array<std::uint32_t, kLayers>> counts(width * static_cast<std::size_t>(view.height()));
  for (const Dot& d : dots)
    ++counts[static_cast<std::size_t>(view.py(d.p)) * width + static_cast<std::size_t>(view.px(d.p))]
           [static_cast<std::size_t>(d.layer)];

  PngImage map(view.width(), view.height(), kBackground);
  for (std::size_t k = 1; k < path.size(); ++k)
    map.line(view.px(path[k - 1]), view.py(path[k - 1]), view.px(path[k]), view.py(path[k]), kPathColour);
  // Each pixel in the colour of its commonest kind of return.
  for (std::size_t i = 0; i < counts.size(); ++i) {
    std::size_t commonest = 0;
    for (std::size_t layer = 1; layer < kLayers; ++layer)
      if (counts[i][layer] >= counts[i][commonest]) commonest = layer;
    if (counts[i][commonest] == 0) continue;
    map.set(static_cast<int>(i % width), static_cast<int>(i / width), colourOf(static_cast<Layer>(commonest)));
  }

  PngImage image(view.width() + 2 * kMargin, view.height() + kTitleHeight + kLegendHeight + kMargin, kBackground);
  image.text(kMargin, kMargin / 2, title, kTextColour, kTextScale);
  image.paste(map, kMargin, kTitleHeight);
  image.legend(kMargin, kTitleHeight + view.height() + kMargin / 2,
               {{kReobservedColour, "RE-OBSERVED"},
                {kNotReobservedColour, "NEVER RE-OBSERVED"},
                {kRemovedReobservedColour, "REMOVED, RE-OBSERVED"},
                {kRemovedNotReobservedColour, "REMOVED, NEVER RE-OBSERVED"},
                {kPathColour, "SENSOR PATH"}},
               kTextColour, kTextScale);
  return image;
}

}  // namespace scanfilter
