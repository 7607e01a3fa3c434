#pragma once
// A filter's labels on a log against the log's multi-view consistency
// (multiview_consistency.hpp): how much of what it removed was seen again
// from elsewhere (likely real surface) and how much never was (likely an
// artefact), overall, by range band and by incidence band.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "scanfilter/multiview_consistency.hpp"

namespace scanfilter {

// Range bands (m): 0-2, 2-4, 4-6, 6-10, >= 10. The first three are the
// false-deletion bands of the simulated comparison (a 6 m URG's whole range);
// the SICK logs reach tens of metres, hence two more.
inline constexpr std::array<double, 4> kConsistencyRangeEdges = {2.0, 4.0, 6.0, 10.0};
inline constexpr std::size_t kConsistencyRangeBands = kConsistencyRangeEdges.size() + 1;
// Incidence bands (deg): 0-30, 30-60, 60-75, 75-90, then "unknown" (no
// surface could be estimated, incidence_angle.hpp). 75° is where the
// simulator's spot starts to deform (scene.hpp grazing_angle_deg).
inline constexpr std::array<double, 3> kIncidenceEdgesDeg = {30.0, 60.0, 75.0};
inline constexpr std::size_t kUnknownIncidenceBand = kIncidenceEdgesDeg.size() + 1;
inline constexpr std::size_t kIncidenceBands = kUnknownIncidenceBand + 1;

std::string rangeBandName(std::size_t band);      // "0-2 m", ..., ">= 10 m"
std::string incidenceBandName(std::size_t band);  // "0-30°", ..., "unknown"

// Counts of returns; the shares are NaN when they divide by zero.
struct ConsistencyCounts {
  std::size_t returns = 0;
  std::size_t reobserved = 0;
  std::size_t removed = 0;
  std::size_t removed_reobserved = 0;

  void add(const ConsistencyCounts& o) {
    returns += o.returns;
    reobserved += o.reobserved;
    removed += o.removed;
    removed_reobserved += o.removed_reobserved;
  }
  std::size_t notReobserved() const { return returns - reobserved; }
  std::size_t removedNotReobserved() const { return removed - removed_reobserved; }
  double removedShare() const { return share(removed, returns); }
  double reobservedShare() const { return share(reobserved, returns); }
  // The false-deletion proxy.
  double removedOfReobserved() const { return share(removed_reobserved, reobserved); }
  double removedOfNotReobserved() const { return share(removedNotReobserved(), notReobserved()); }
  // How much likelier a never re-observed return is to be removed than a
  // re-observed one: 1 removes blindly, higher is more selective.
  double selectivity() const { return removedOfNotReobserved() / removedOfReobserved(); }

  static double share(std::size_t part, std::size_t whole);
};

struct ConsistencyScore {
  ConsistencyCounts all;
  std::array<ConsistencyCounts, kConsistencyRangeBands> by_range{};
  std::array<ConsistencyCounts, kIncidenceBands> by_incidence{};
};

// One log as the measure sees it, whatever filter ran: each return
// re-observed or not, its range band and its incidence band. Built once per
// log, then scores any number of filters' labels.
class MultiviewConsistency {
 public:
  MultiviewConsistency(std::span<const Scan> scans, const SensorInfo& sensor, const MultiviewParams& params = {});

  const ReobservationMap& reobservation() const { return reobservation_; }
  // labels: per scan, per beam, as a filter gave them (PointCode).
  ConsistencyScore score(std::span<const std::vector<std::uint8_t>> labels) const;

 private:
  ReobservationMap reobservation_;
  std::vector<std::vector<std::uint8_t>> range_band_;
  std::vector<std::vector<std::uint8_t>> incidence_band_;
};

}  // namespace scanfilter
