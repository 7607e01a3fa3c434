#pragma once
#include "scanfilter/beam_mask.hpp"
#include "scanfilter/scan.hpp"

namespace scanfilter {

// Returns on the near side of a depth edge: a return with a background
// return (`background[j]`) within `half_width_beams` beams of it that lies
// more than `depth_step` farther. Where a beam's footprint straddles an edge
// the return is a mix of the near and the far surface, placed a little
// beyond the near surface's end; such returns are where they are only from
// that viewpoint, so step 2 does not let them build obstacle cells (seen from
// many places they smear an edge outwards, and beams passing just beside it
// then seem to cross it). The caller says what counts as background (step 2:
// the returns it keeps).
BeamMask nearSideOfDepthEdge(const Scan& scan, const BeamMask& background, int half_width_beams, double depth_step);

}  // namespace scanfilter
