#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "scanfilter/line_reader.hpp"
#include "scanfilter/plausible_bounds.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/stamp_order.hpp"

namespace scanfilter {

// Streams a `.scanlog.jsonl` file (docs/data-formats.md), one scan
// at a time, validating every field. Unknown keys are kept, never rejected.
class ScanLogReader final : public ScanSource {
 public:
  explicit ScanLogReader(const std::string& path, bool warn_stamps = true);

  const ScanLogHeader& header() const override { return header_; }
  bool next(ScanRecord& record) override;
  std::size_t stampRegressions() const override { return stamp_order_.regressions(); }
  std::size_t stampRepeats() const override { return stamp_order_.repeats(); }

  // Upper bound on a believable range (m): larger values are corrupt data,
  // not "out of range", and are rejected.
  static constexpr double kImplausibleRange = kMaxPlausibleRange;
  // Upper bound on beams per scan: guards memory against corrupt input.
  static constexpr std::size_t kMaxBeams = 1u << 20;

 private:
  void parseHeader();
  void parseScan(const nlohmann::ordered_json& object, std::string_view stamp_text, Scan& scan);

  LineReader lines_;
  ScanLogHeader header_;
  StampOrder stamp_order_;
};

}  // namespace scanfilter
