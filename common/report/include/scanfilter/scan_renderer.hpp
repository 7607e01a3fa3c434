#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/png_image.hpp"
#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

struct RenderOptions {
  int panel_pixels = 800;  // the longer side of each panel
  std::string title;
};

// Draws scans in the world frame as PNG: "before" (every return, coloured by
// truth when the log has it) beside "after" (kept points in black, removed
// ones in the colour of the step that removed them), with the trajectory.
class ScanRenderer {
 public:
  void add(const Scan& scan, const SensorInfo& sensor, std::span<const std::uint8_t> labels);
  void save(const std::string& path, const RenderOptions& options) const;
  PngImage draw(const RenderOptions& options) const;
  std::size_t pointCount() const { return points_.size(); }

 private:
  struct Point {
    Eigen::Vector2d p;
    std::uint8_t truth;  // 255 when unknown
    std::uint8_t label;
  };
  std::vector<Point> points_;
  std::vector<Eigen::Vector2d> trajectory_;
};

}  // namespace scanfilter
