#include "scanfilter/consistency_score.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "scanfilter/incidence_angle.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/value_band.hpp"

namespace scanfilter {

namespace {

template <std::size_t N>
std::string bandName(const std::array<double, N>& edges, std::size_t band, const char* unit) {
  std::ostringstream out;
  if (band == 0) out << "0-" << edges[0] << unit;
  else if (band < N) out << edges[band - 1] << "-" << edges[band] << unit;
  else out << ">= " << edges[N - 1] << unit;
  return out.str();
}

void count(ConsistencyCounts& c, bool reobserved, bool removed) {
  ++c.returns;
  c.reobserved += reobserved;
  c.removed += removed;
  c.removed_reobserved += reobserved && removed;
}

}  // namespace

std::string rangeBandName(std::size_t band) { return bandName(kConsistencyRangeEdges, band, " m"); }

std::string incidenceBandName(std::size_t band) {
  if (band == kUnknownIncidenceBand) return "unknown";
  // The last known band ends at 90°, not "at or above 75°".
  if (band == kIncidenceEdgesDeg.size()) {
    std::ostringstream out;
    out << kIncidenceEdgesDeg.back() << "-90°";
    return out.str();
  }
  return bandName(kIncidenceEdgesDeg, band, "°");
}

double ConsistencyCounts::share(std::size_t part, std::size_t whole) {
  return whole ? static_cast<double>(part) / static_cast<double>(whole) : std::numeric_limits<double>::quiet_NaN();
}

MultiviewConsistency::MultiviewConsistency(std::span<const Scan> scans, const SensorInfo& sensor,
                                           const MultiviewParams& params)
    : reobservation_(findReobservedReturns(scans, sensor, params)) {
  range_band_.resize(scans.size());
  incidence_band_.resize(scans.size());
  for (std::size_t s = 0; s < scans.size(); ++s) {
    const std::vector<double> incidence = incidenceAnglesDeg(scans[s], sensor, params.surface_tolerance);
    range_band_[s].resize(scans[s].size());
    incidence_band_[s].resize(scans[s].size());
    for (std::size_t i = 0; i < scans[s].size(); ++i) {
      range_band_[s][i] = static_cast<std::uint8_t>(bandOf(scans[s].ranges[i], kConsistencyRangeEdges));
      incidence_band_[s][i] = static_cast<std::uint8_t>(
          std::isnan(incidence[i]) ? kUnknownIncidenceBand : bandOf(incidence[i], kIncidenceEdgesDeg));
    }
  }
}

ConsistencyScore MultiviewConsistency::score(std::span<const std::vector<std::uint8_t>> labels) const {
  if (labels.size() != reobservation_.size())
    throw std::invalid_argument("multiview consistency: labels for a different number of scans");
  ConsistencyScore out;
  for (std::size_t s = 0; s < labels.size(); ++s) {
    if (labels[s].size() != reobservation_[s].size())
      throw std::invalid_argument("multiview consistency: labels for a different number of beams");
    for (std::size_t i = 0; i < labels[s].size(); ++i) {
      if (reobservation_[s][i] == Reobservation::kNoReturn) continue;
      const bool reobserved = reobservation_[s][i] == Reobservation::kReobserved;
      const bool removed = isRemovedCode(labels[s][i]);
      count(out.all, reobserved, removed);
      count(out.by_range[range_band_[s][i]], reobserved, removed);
      count(out.by_incidence[incidence_band_[s][i]], reobserved, removed);
    }
  }
  return out;
}

}  // namespace scanfilter
