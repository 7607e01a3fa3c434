#include "scanfilter/scan_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scanfilter/png_image.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"
#include "scanfilter/world_viewport.hpp"

namespace scanfilter {

namespace {

constexpr std::uint8_t kUnknown = 255;
constexpr Rgb kBackground{255, 255, 255};
constexpr Rgb kValidColour{40, 40, 40};
constexpr Rgb kUnlabelledColour{110, 110, 110};
constexpr Rgb kJumpColour{230, 30, 30};
constexpr Rgb kMisdetectedColour{30, 90, 230};
constexpr Rgb kTrajectoryColour{40, 170, 70};
constexpr Rgb kTextColour{0, 0, 0};
constexpr int kMargin = 20;
constexpr int kTitleHeight = 40;
constexpr int kLegendHeight = 40;
constexpr int kTextScale = 2;

Rgb colourOf(std::uint8_t code) {
  switch (static_cast<PointCode>(code)) {
    case PointCode::kJump: return kJumpColour;
    case PointCode::kMisdetected: return kMisdetectedColour;
    default: return kValidColour;
  }
}

}  // namespace

void ScanRenderer::add(const Scan& scan, const SensorInfo& sensor, std::span<const std::uint8_t> labels) {
  trajectory_.push_back(sensorOrigin(scan.pose, sensor.mount));
  for (std::size_t i = 0; i < scan.size(); ++i) {
    if (!scan.hasReturn(i)) continue;
    const std::uint8_t truth = scan.truth.empty() ? kUnknown : scan.truth[i];
    const std::uint8_t label = labels.empty() ? static_cast<std::uint8_t>(PointCode::kValid) : labels[i];
    points_.push_back({beamToWorld(scan, sensor, i), truth, label});
  }
}

void ScanRenderer::save(const std::string& path, const RenderOptions& options) const { draw(options).save(path); }

PngImage ScanRenderer::draw(const RenderOptions& options) const {
  WorldBounds bounds;
  for (const auto& pt : points_) bounds.include(pt.p);
  for (const auto& t : trajectory_) bounds.include(t);
  const WorldViewport view = bounds.viewport(options.panel_pixels);
  const int pw = view.width(), ph = view.height();

  const auto drawPanel = [&](bool after) {
    PngImage panel(pw, ph, kBackground);
    for (std::size_t k = 1; k < trajectory_.size(); ++k)
      panel.line(view.px(trajectory_[k - 1]), view.py(trajectory_[k - 1]), view.px(trajectory_[k]),
                 view.py(trajectory_[k]), kTrajectoryColour);
    // Removed points first, so kept points stay readable on top.
    for (int pass = 0; pass < 2; ++pass) {
      for (const auto& pt : points_) {
        const std::uint8_t code = after ? pt.label : pt.truth;
        const bool removed = isRemovedCode(code);
        if ((pass == 0) != removed) continue;
        const Rgb colour = code == kUnknown ? kUnlabelledColour : colourOf(code);
        if (removed) panel.disc(view.px(pt.p), view.py(pt.p), 1, colour);
        else panel.set(view.px(pt.p), view.py(pt.p), colour);
      }
    }
    return panel;
  };

  constexpr int kPanels = 2;
  constexpr int kCaptionY = kMargin + 2 * kTextScale * 4;
  PngImage image(kPanels * pw + (kPanels + 1) * kMargin, ph + kTitleHeight + kLegendHeight + kMargin, kBackground);
  image.text(kMargin, kMargin / 2, options.title, kTextColour, kTextScale);
  const int before_x = kMargin, after_x = 2 * kMargin + pw;
  // A real recording has no truth: its points are drawn unlabelled.
  const bool has_truth =
      std::any_of(points_.begin(), points_.end(), [](const auto& pt) { return pt.truth != kUnknown; });
  image.text(before_x, kCaptionY, has_truth ? "BEFORE (COLOUR = TRUTH)" : "BEFORE (NO TRUTH IN THE LOG)", kTextColour,
             kTextScale);
  image.paste(drawPanel(false), before_x, kTitleHeight + kMargin / 2);
  image.text(after_x, kCaptionY, "AFTER (COLOUR = FILTER LABEL)", kTextColour, kTextScale);
  image.paste(drawPanel(true), after_x, kTitleHeight + kMargin / 2);

  // Legend.
  const int ly = ph + kTitleHeight + kMargin;
  std::vector<std::pair<Rgb, std::string>> entries = {{kValidColour, "VALID"},
                                                       {kJumpColour, "JUMP"},
                                                       {kMisdetectedColour, "MISDETECTED"},
                                                       {kTrajectoryColour, "SENSOR PATH"}};
  if (!has_truth) entries.insert(entries.begin(), {kUnlabelledColour, "NO TRUTH"});
  image.legend(kMargin, ly, entries, kTextColour, kTextScale);
  return image;
}

}  // namespace scanfilter
