#pragma once
// Command-line value checks whose errors say what was expected:
// "--rate: expected a number >= 0 (scans per second), got -5".
// CLI11 2.1's NonNegativeNumber names DBL_MAX as the upper limit, and it
// reads "-1" given to an unsigned option as 2^64 - 1 without a word.
#include <cmath>
#include <limits>
#include <string>

#include <CLI/CLI.hpp>

namespace scanfilter::cli {

// A finite number from `lo` to `hi`; `unit` is said in the message, e.g.
// "m" or "scans per second".
inline CLI::Validator numberFromTo(double lo, double hi, const std::string& unit) {
  const std::string range = std::isinf(hi) ? ">= " + CLI::detail::to_string(lo)
                                           : "from " + CLI::detail::to_string(lo) + " to " + CLI::detail::to_string(hi);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0;
        const bool number = CLI::detail::lexical_cast(text, value) && std::isfinite(value);
        if (number && value >= lo && value <= hi) return {};
        return "expected a number " + range + " (" + unit + "), got " + text;
      },
      "NUMBER " + range);
}

// A finite number at least `lo`.
inline CLI::Validator numberAtLeast(double lo, const std::string& unit) {
  return numberFromTo(lo, std::numeric_limits<double>::infinity(), unit);
}

// A whole number 0 or more, digits only.
inline CLI::Validator wholeNumber(const std::string& what) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string::npos;
        return digits ? std::string() : "expected " + what + ": a whole number >= 0, got " + text;
      },
      "UINT");
}

}  // namespace scanfilter::cli
