#pragma once
#include <cstdint>

namespace scanfilter {

// Two signed grid coordinates packed into one 64-bit key, x in the high
// half and y in the low, each as its 32-bit two's complement: the key of
// the hash maps and sorted lists that hold grid cells (or tiles, buckets)
// by position. Distinct coordinates give distinct keys.
inline std::uint64_t cellKey(std::int32_t x, std::int32_t y) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) | static_cast<std::uint32_t>(y);
}

}  // namespace scanfilter
