#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "scanfilter/multiview_consistency.hpp"
#include "scanfilter/png_image.hpp"

namespace scanfilter {

// A map of every return of a log in the world frame, coloured by the
// multi-view consistency and a filter's labels: re-observed returns grey,
// never re-observed ones light grey, removed ones red when they were
// re-observed (likely a false deletion) and blue when they never were
// (likely an artefact); the sensor's path in green. Each pixel shows the
// commonest kind of return in it (ties to the removed kinds), so a dense log
// shows where removal dominates, not every single removed return.
// `longer_side_pixels`: the map's longer side.
PngImage drawRemovalsByReobservation(std::span<const Scan> scans, const SensorInfo& sensor,
                                     const ReobservationMap& reobservation,
                                     std::span<const std::vector<std::uint8_t>> labels, const std::string& title,
                                     int longer_side_pixels);

}  // namespace scanfilter
