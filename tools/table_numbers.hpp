#pragma once
// Numbers as the commands' markdown tables print them.
#include <cstddef>
#include <cstdio>
#include <string>

namespace scanfilter::cli {

// printf-style formatting of one number.
inline std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}
// A share as "12.34 %".
inline std::string pct(double share) { return fmt("%.2f %%", 100.0 * share); }
// part of whole as "12.34 %" (0 when there is no whole).
inline std::string pct(std::size_t part, std::size_t whole) {
  return pct(whole ? static_cast<double>(part) / static_cast<double>(whole) : 0.0);
}

}  // namespace scanfilter::cli
