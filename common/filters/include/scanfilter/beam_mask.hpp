#pragma once
#include <cstdint>
#include <vector>

namespace scanfilter {

// One yes/no per beam of a scan (which returns are usable, kept, at an edge),
// a byte each: step 2 reads such flags several times per beam, and
// std::vector<bool>'s bit arithmetic for each read and write was 7 % of its
// instructions at 3,600 beams (docs/performance.md).
using BeamMask = std::vector<std::uint8_t>;

}  // namespace scanfilter
