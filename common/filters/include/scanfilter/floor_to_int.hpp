#pragma once
#include <cstdint>

namespace scanfilter {

// static_cast<std::int32_t>(std::floor(x)) for x within the int32 range, in
// two instructions: without SSE4.1 (the Debian baseline) std::floor is a
// library call, and step 2 takes a cell index several times per beam.
inline std::int32_t floorToInt(double x) {
  const auto i = static_cast<std::int32_t>(x);
  return i - (x < static_cast<double>(i));
}

}  // namespace scanfilter
