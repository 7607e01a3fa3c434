#pragma once
// Beam masks the penetration filter's parts take from one frame (internal to
// scanfilter_filters: penetration_filter.cpp and the files beside it that
// define the rest of PenetrationFilter).
#include <cstdint>
#include <span>

#include "scanfilter/beam_mask.hpp"
#include "scanfilter/point_code.hpp"
#include "scanfilter/scan.hpp"

namespace scanfilter {

// The returns this frame keeps so far: the ones that pull the alignment's fit
// (step 1's jump points lie on no surface), and the far side of a depth edge
// that counts (ghosts behind a mirror or a pane that this frame has marked
// do not silence the pane's own returns next to them).
inline BeamMask keptReturns(std::span<const std::uint8_t> labels) {
  BeamMask kept(labels.size());
  for (std::size_t i = 0; i < labels.size(); ++i) kept.set(i, labels[i] == static_cast<std::uint8_t>(PointCode::kValid));
  return kept;
}

// Every return, kept or not (the free-space check's far side of an edge).
inline BeamMask allReturns(const Scan& scan) {
  BeamMask returns(scan.size());
  for (std::size_t i = 0; i < scan.size(); ++i) returns.set(i, scan.hasReturn(i));
  return returns;
}

}  // namespace scanfilter
