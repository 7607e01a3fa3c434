#include "scanfilter/scan_renderer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scanfilter/png_image.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan_geometry.hpp"

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

// World metres to panel pixels, y up.
struct Viewport {
  Eigen::Vector2d min;
  double scale;  // pixels per metre
  int height;
  int px(const Eigen::Vector2d& p) const { return static_cast<int>((p.x() - min.x()) * scale); }
  int py(const Eigen::Vector2d& p) const { return height - 1 - static_cast<int>((p.y() - min.y()) * scale); }
};

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
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (const auto& pt : points_) lo = lo.cwiseMin(pt.p), hi = hi.cwiseMax(pt.p);
  for (const auto& t : trajectory_) lo = lo.cwiseMin(t), hi = hi.cwiseMax(t);
  if (!std::isfinite(lo.x())) lo = hi = Eigen::Vector2d::Zero();
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(1e-3);
  const double scale = options.panel_pixels / std::max(extent.x(), extent.y());
  const int pw = static_cast<int>(extent.x() * scale) + 1;
  const int ph = static_cast<int>(extent.y() * scale) + 1;
  const Viewport view{lo, scale, ph};

  const auto drawPanel = [&](bool after) {
    PngImage panel(pw, ph, kBackground);
    for (std::size_t k = 1; k < trajectory_.size(); ++k)
      panel.line(view.px(trajectory_[k - 1]), view.py(trajectory_[k - 1]), view.px(trajectory_[k]),
                 view.py(trajectory_[k]), kTrajectoryColour);
    // Removed points first, so kept points stay readable on top.
    for (int pass = 0; pass < 2; ++pass) {
      for (const auto& pt : points_) {
        const std::uint8_t code = after ? pt.label : pt.truth;
        const bool removed = code == static_cast<std::uint8_t>(PointCode::kJump) ||
                             code == static_cast<std::uint8_t>(PointCode::kMisdetected);
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
  image.text(before_x, kCaptionY, "BEFORE (COLOUR = TRUTH)", kTextColour, kTextScale);
  image.paste(drawPanel(false), before_x, kTitleHeight + kMargin / 2);
  image.text(after_x, kCaptionY, "AFTER (COLOUR = FILTER LABEL)", kTextColour, kTextScale);
  image.paste(drawPanel(true), after_x, kTitleHeight + kMargin / 2);

  // Legend.
  const int ly = ph + kTitleHeight + kMargin;
  int lx = kMargin;
  const std::pair<Rgb, const char*> entries[] = {{kValidColour, "VALID"},
                                                 {kJumpColour, "JUMP"},
                                                 {kMisdetectedColour, "MISDETECTED"},
                                                 {kTrajectoryColour, "SENSOR PATH"}};
  for (const auto& [colour, name] : entries) {
    image.fillRect(lx, ly, lx + 14, ly + 14, colour);
    image.text(lx + 22, ly, name, kTextColour, kTextScale);
    lx += 40 + static_cast<int>(std::string(name).size()) * 6 * kTextScale;
  }
  return image;
}

}  // namespace scanfilter
