#pragma once
#include <compare>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace scanfilter {

// A scan's time stamp as integer nanoseconds. ROS's (sec, nanosec) and a
// log's decimal seconds pass through the filter bit-exact this way: a double
// resolves only about 240 ns at 1.7e9 s, and exact-time synchronisers and TF
// lookups downstream key on the stamp. Durations between stamps may be
// doubles (secondsSince); a stamp itself never is.
class Stamp {
 public:
  static constexpr std::int64_t kNanosPerSecond = 1'000'000'000;

  constexpr Stamp() = default;
  static constexpr Stamp fromNanoseconds(std::int64_t ns) { return Stamp(ns); }
  // ROS builtin_interfaces/Time: nanosec must be below 1e9.
  static constexpr Stamp fromSecNanosec(std::int64_t sec, std::uint32_t nanosec) {
    return Stamp(sec * kNanosPerSecond + static_cast<std::int64_t>(nanosec));
  }
  // For computed stamps only (the simulator's frame times): never for a
  // stamp that came from outside, which would lose its exact value.
  static Stamp fromSeconds(double seconds);

  // Decimal seconds as written in a log ("12", "12.3", "1732000000.200700001",
  // "1.7e9"), exact to the nanosecond; digits finer than 1 ns are rounded to
  // the nearest nanosecond. Nothing when the text is not a decimal number or
  // out of range.
  static std::optional<Stamp> parseDecimal(std::string_view text);

  constexpr std::int64_t nanoseconds() const { return ns_; }
  // ROS (sec, nanosec): sec rounded down, 0 <= nanosec < 1e9.
  constexpr std::int64_t sec() const { return floorDiv(ns_); }
  constexpr std::uint32_t nanosec() const { return static_cast<std::uint32_t>(ns_ - sec() * kNanosPerSecond); }
  // Shortest decimal seconds that parse back to this stamp: "12.3", "7", "-0.5".
  std::string toDecimal() const;

  // The time from `earlier` to this stamp in seconds (a duration, not a stamp).
  double secondsSince(Stamp earlier) const { return static_cast<double>(ns_ - earlier.ns_) * 1e-9; }

  friend constexpr auto operator<=>(Stamp, Stamp) = default;

 private:
  constexpr explicit Stamp(std::int64_t ns) : ns_(ns) {}
  static constexpr std::int64_t floorDiv(std::int64_t ns) {
    return ns / kNanosPerSecond - (ns % kNanosPerSecond < 0 ? 1 : 0);
  }
  std::int64_t ns_ = 0;
};

}  // namespace scanfilter
