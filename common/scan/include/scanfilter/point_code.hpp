#pragma once
#include <cstdint>

namespace scanfilter {

// Per-beam codes of the scan log format (`truth` and `labels`).
enum class PointCode : std::uint8_t {
  kValid = 0,        // kept
  kJump = 1,         // removed by step 1 (jump filter)
  kMisdetected = 2,  // removed by step 2 (penetration filter)
  kNoReturn = 3,     // out of range or missing
};

inline constexpr int kPointCodeCount = 4;

inline constexpr bool isValidPointCode(int code) { return code >= 0 && code < kPointCodeCount; }

// True for the codes of a beam a filter removed (by either step).
inline constexpr bool isRemovedCode(std::uint8_t code) {
  return code == static_cast<std::uint8_t>(PointCode::kJump) ||
         code == static_cast<std::uint8_t>(PointCode::kMisdetected);
}

inline constexpr const char* pointCodeName(PointCode code) {
  switch (code) {
    case PointCode::kValid: return "valid";
    case PointCode::kJump: return "jump";
    case PointCode::kMisdetected: return "misdetected";
    case PointCode::kNoReturn: return "no_return";
  }
  return "unknown";
}

}  // namespace scanfilter
