#pragma once
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "scanfilter/penetration_grid.hpp"
#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

// Parameters of the log-odds occupancy map (config/map_publisher.yaml documents them).
struct OccupancyGridParams {
  double resolution = 0.05;        // m per cell
  double hit_probability = 0.7;    // P(occupied | beam ended here)
  double miss_probability = 0.4;   // P(occupied | beam passed through)
  double clamp_min = 0.12;         // probability bounds, so the map can change its mind
  double clamp_max = 0.97;
  double occupied_threshold = 0.65;  // map_server: above is occupied
  double free_threshold = 0.196;     // map_server: below is free
  bool clear_on_no_return = false;   // "no return" beams clear free space...
  double no_return_clear_range = 4.0;  // ...up to this far (m)
};

// Axis-aligned rectangle of cells, inclusive.
struct CellBox {
  CellIndex lo{0, 0};
  CellIndex hi{-1, -1};
  bool empty() const { return hi.x < lo.x || hi.y < lo.y; }
  void include(CellIndex c);
  std::int64_t width() const { return empty() ? 0 : hi.x - lo.x + 1; }
  std::int64_t height() const { return empty() ? 0 : hi.y - lo.y + 1; }
};

// A log-odds occupancy grid in the world frame, stored in 64 x 64-cell tiles
// created as the robot explores, so memory follows the area seen. Each kept
// point updates the cells along its beam as free and its end cell as
// occupied; removed points update nothing.
class OccupancyGrid {
 public:
  static constexpr int kTileBits = 6;
  static constexpr int kTileSide = 1 << kTileBits;

  explicit OccupancyGrid(const OccupancyGridParams& params);

  // Integrates one labelled scan (labels: point_code.hpp; empty = all kept).
  void integrate(const Scan& scan, const SensorInfo& sensor, const std::vector<std::uint8_t>& labels);

  // Occupancy probability of a cell; 0.5 where nothing was seen.
  double probability(CellIndex c) const;
  // ROS OccupancyGrid value: -1 unknown, 0 free ... 100 occupied.
  std::int8_t rosValue(CellIndex c) const;
  // Log-odds of a cell (0 unknown); for exact comparisons.
  float logOdds(CellIndex c) const;
  void setLogOdds(CellIndex c, float value);

  CellIndex cellOf(const Eigen::Vector2d& p) const;
  Eigen::Vector2d cellCentre(CellIndex c) const;
  const CellBox& bounds() const { return bounds_; }
  // Cells changed since the last call (for incremental updates), then reset.
  CellBox takeChanged();
  std::size_t tileCount() const { return tiles_.size(); }
  std::size_t memoryBytes() const;
  const OccupancyGridParams& params() const { return params_; }
  std::size_t scansIntegrated() const { return scans_; }

 private:
  struct Tile {
    std::vector<float> log_odds = std::vector<float>(kTileSide * kTileSide, 0.0f);
  };
  float* cell(CellIndex c);  // creates the tile
  const float* findCell(CellIndex c) const;
  void update(CellIndex c, float delta);
  void traceFree(const Eigen::Vector2d& from, const Eigen::Vector2d& to, bool mark_end_occupied);

  OccupancyGridParams params_;
  float hit_, miss_, min_, max_;
  std::unordered_map<std::uint64_t, std::unique_ptr<Tile>> tiles_;
  CellBox bounds_;
  CellBox changed_;
  std::size_t scans_ = 0;
};

}  // namespace scanfilter
