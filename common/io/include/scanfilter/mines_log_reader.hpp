#pragma once
#include <string>
#include <vector>

#include "scanfilter/line_reader.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/stamp_order.hpp"

namespace scanfilter {

// The Mines ParisTech robot of the CoreSLAM / BreezySLAM logs (exp1.dat,
// exp2.dat): a differential drive with a Hokuyo URG-04LX. Values from
// BreezySLAM examples/mines.py and python/breezyslam/sensors.py.
struct MinesRobotModel {
  double wheel_radius = 0.077;       // m
  double half_axle = 0.165;          // m, wheel to robot centre
  double ticks_per_revolution = 2000.0;  // BreezySLAM: ticks * 180 / 2000 degrees with ds = r (φL + φR)
  double laser_offset = 0.145;       // m, laser ahead of the robot centre
  int beams = 682;
  double angle_min_deg = -120.0;     // beam 0; angles grow counter-clockwise
  double field_of_view_deg = 240.0;  // beam 681 at +120°
  double no_return_below = 0.020;    // m: 0 and the URG error codes 1-19 mm
  double range_max = 5.6;            // m, URG-04LX specification
};

// Streams a Mines URG-04LX log: one scan per line of whitespace-separated
// values, token 0 the time in µs, tokens 2 and 3 the cumulative left and
// right wheel-encoder ticks, tokens 24-705 the 682 ranges in mm (the 707th
// value is dropped, as BreezySLAM does). The log has no poses: they are dead
// reckoned from the ticks (midpoint integration from the first scan at the
// origin), so they drift as wheel odometry does.
class MinesLogReader final : public ScanSource {
 public:
  // How header().source begins: what tells a reader these poses are wheel
  // odometry, not corrected ones.
  static constexpr const char* kSourcePrefix = "Mines URG-04LX log (poses dead-reckoned from wheel ticks) ";

  explicit MinesLogReader(const std::string& path, const MinesRobotModel& model = {}, bool warn_stamps = true);

  const ScanLogHeader& header() const override { return header_; }
  bool next(ScanRecord& record) override;
  std::size_t stampRegressions() const override { return stamp_order_.regressions(); }
  std::size_t stampRepeats() const override { return stamp_order_.repeats(); }

  // True when a line looks like a Mines log line (707 fields, integer first).
  static bool looksLikeMinesLine(const std::string& line);

 private:
  long long integerField(const std::vector<std::string>& tokens, std::size_t index, const char* field) const;
  void integrateOdometry(long long left_ticks, long long right_ticks);

  LineReader lines_;
  StampOrder stamp_order_;
  MinesRobotModel model_;
  ScanLogHeader header_;
  Pose2 pose_;
  bool have_ticks_ = false;
  long long left_ticks_ = 0;
  long long right_ticks_ = 0;
};

}  // namespace scanfilter
