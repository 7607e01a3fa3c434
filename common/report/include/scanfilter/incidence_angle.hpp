#pragma once
#include <vector>

#include "scanfilter/scan.hpp"
#include "scanfilter/sensor_info.hpp"

namespace scanfilter {

// Per beam of a scan: the angle (deg, 0-90) between the beam and the normal of
// the surface it hit, the surface's direction taken from the beam's two
// neighbouring returns (localSurfaceDirection with `surface_tolerance`). NaN
// where no surface can be estimated: no return, an end of the scan, a
// missing neighbour, or three returns that do not lie on one line.
std::vector<double> incidenceAnglesDeg(const Scan& scan, const SensorInfo& sensor, double surface_tolerance);

}  // namespace scanfilter
