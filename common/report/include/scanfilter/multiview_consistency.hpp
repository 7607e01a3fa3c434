#pragma once
// Multi-view consistency: which returns of a log were seen again from
// elsewhere. A real surface is hit again whenever the robot passes it from
// another place; a mixed return, a ghost behind glass or a return displaced
// at grazing incidence depends on where the sensor stood and rarely lands in
// the same place twice. On recordings without truth, a filter that removes
// re-observed returns is likely deleting real surface (the false-deletion
// proxy of docs/accuracy.md), one that removes never re-observed returns is
// likely removing artefacts.
#include <cstdint>
#include <span>
#include <vector>

#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

struct MultiviewParams {
  // Grid every return of the log is put into (m). 5 cm: about a SICK's or a
  // URG's range noise and the project's map resolution, so a surface seen
  // again lands in its own cell or the next.
  double cell_size = 0.05;
  // Cells on each side of a return's cell that count as "the same place":
  // 1 looks at the 3 x 3 block, so noise across a cell edge still matches.
  int neighbourhood_cells = 1;
  // Grid the sensor's position is rounded down to (m): one viewpoint per
  // square metre, so the scans of one pass by a wall are one viewpoint.
  double position_cell = 1.0;
  // Viewpoints within this many position cells (Chebyshev) of the return's
  // own do not count: from the next square metre a ghost or a mixed return
  // can still land in the same place.
  int adjacent_positions = 1;
  // Distinct viewpoints, beyond the adjacent ones, that must have hit the
  // neighbourhood for a return to be re-observed.
  int min_viewpoints = 4;
  // For the incidence bands (consistency_score.hpp): a return's two
  // neighbours in its scan describe its surface when it lies within this of
  // their chord (m); a few times the range noise, so a wall stays one
  // surface and a corner or a depth step does not.
  double surface_tolerance = 0.05;
};

enum class Reobservation : std::uint8_t {
  kNoReturn,       // the beam has no return
  kReobserved,     // seen again from enough far viewpoints
  kNotReobserved,  // never (or too rarely) seen from elsewhere
};

// Per scan, per beam.
using ReobservationMap = std::vector<std::vector<Reobservation>>;

// Puts every return of the log (all of them: before any filter) into the grid
// with the viewpoint that saw it (the sensor's origin, via the scan's pose and
// the mount), then classifies each return by the viewpoints that hit the
// cells around it.
ReobservationMap findReobservedReturns(std::span<const Scan> scans, const SensorInfo& sensor,
                                       const MultiviewParams& params = {});

}  // namespace scanfilter
