#pragma once
// The multi-view consistency section of `scanfilter report-real`: on real
// logs (no truth), every filter's removals against the returns seen again
// from elsewhere (common/report/include/scanfilter/consistency_score.hpp):
// ours with its defaults and paper-literal, and the baselines of
// `scanfilter bench-accuracy` at their published defaults.
#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "scanfilter/accuracy/filter_score.hpp"
#include "scanfilter/consistency_score.hpp"
#include "scanfilter/filter_config.hpp"
#include "scanfilter/sim/labelled_log.hpp"

namespace scanfilter::cli {

struct ConsistencyFilter {
  std::string name;
  std::string parameters;  // as the filters table shows them
  accuracy::FilterFactory make;
};

// Ours (defaults from `ours`) first, ours paper-literal when given, then
// every baseline of the comparison at its defaults, and laser_filters'
// shadows filter with neighbors 1 (the setting the simulated comparison tunes
// it to).
std::vector<ConsistencyFilter> consistencyFilters(const FilterConfig& ours, const std::optional<FilterConfig>& literal);

class RealConsistencyReport {
 public:
  explicit RealConsistencyReport(std::vector<ConsistencyFilter> filters) : filters_(std::move(filters)) {}

  // Runs every filter over the log and scores it. When picture_path is set,
  // also draws what the first filter removed (saved there, linked in the
  // tables as picture_link).
  void add(const sim::LabelledLog& log, const std::string& picture_path, const std::string& picture_link);
  // The markdown tables, every log so far.
  void write(std::ostream& out) const;

 private:
  struct LogResult {
    std::string name;
    std::vector<ConsistencyScore> scores;  // per filter
    std::string picture_link;              // empty: none drawn
  };
  void overallTable(std::ostream& out) const;
  template <std::size_t N>
  void bandTable(std::ostream& out, const char* title, std::array<ConsistencyCounts, N> ConsistencyScore::*bands,
                 std::string (*band_name)(std::size_t)) const;

  std::vector<ConsistencyFilter> filters_;
  std::vector<LogResult> logs_;
};

}  // namespace scanfilter::cli
