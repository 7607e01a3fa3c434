#pragma once
#include <optional>
#include <string>
#include <vector>

#include "scanfilter/line_reader.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/stamp_order.hpp"

namespace scanfilter {

// Streams the scans of a CARMEN log (the format of the classic public indoor
// data sets, plain or gzip): `FLASER` and `ROBOTLASER1` lines; every other
// message is skipped. See docs/data-formats.md for the layouts assumed.
//
// FLASER stores no angles: beam 0 points to the robot's right and the scan
// covers 180° counter-clockwise, so angle_min = -90° and the step is 180°/n
// (180°/(n-1) for an odd n, which then ends at +90°). The mount comes from
// PARAM robot_frontlaser_offset, the range limit from PARAM
// robot_front_laser_max or the option.
class CarmenLogReader final : public ScanSource {
 public:
  CarmenLogReader(const std::string& path, const ScanSourceOptions& options);

  const ScanLogHeader& header() const override { return header_; }
  bool next(ScanRecord& record) override;

  // Scans whose stamp is earlier than the one before. Real logs have them
  // (intel: line 5647); file order is kept as the sequence and they are counted.
  std::size_t stampRegressions() const override { return stamp_order_.regressions(); }
  std::size_t stampRepeats() const override { return stamp_order_.repeats(); }

 private:
  bool readScanLine(std::string& line);
  void checkPlausiblePose(const Pose2& pose) const;
  void parseFlaser(const std::vector<std::string>& tokens, Scan& scan) const;
  void parseRobotLaser(const std::vector<std::string>& tokens, Scan& scan) const;
  double number(const std::vector<std::string>& tokens, std::size_t index, const char* field) const;
  Stamp stamp(const std::vector<std::string>& tokens, std::size_t index) const;
  void setRanges(const std::vector<std::string>& tokens, std::size_t first, std::size_t count,
                 Scan& scan) const;
  [[noreturn]] void fail(const std::string& field, const std::string& problem) const;

  LineReader lines_;
  ScanLogHeader header_;
  std::optional<std::string> pending_;  // first scan line, read to learn the header
  std::size_t pending_line_ = 0;
  std::size_t current_line_ = 0;
  StampOrder stamp_order_;
};

}  // namespace scanfilter
