#include "scanfilter/stamp.hpp"

#include <cmath>
#include <limits>

namespace scanfilter {

namespace {

constexpr std::int64_t kMaxNanoseconds = std::numeric_limits<std::int64_t>::max();
// Exponents beyond this cannot name a stamp within int64 nanoseconds (about
// ±292 years) unless the digits are all zero.
constexpr long kMaxExponent = 40;

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// value * 10 + digit, or false when that leaves int64 nanoseconds.
bool appendDigit(std::int64_t& value, int digit) {
  if (value > (kMaxNanoseconds - digit) / 10) return false;
  value = value * 10 + digit;
  return true;
}

// value = digits * 10^exponent, split out of the text.
struct Decimal {
  bool negative = false;
  std::string digits;  // no leading zeros; empty for zero
  long exponent = 0;
};

std::optional<Decimal> splitDecimal(std::string_view text) {
  Decimal d;
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '-' || text[i] == '+')) d.negative = text[i++] == '-';
  bool any_digit = false;
  auto take_digit = [&](bool fractional) {
    if (!(d.digits.empty() && text[i] == '0')) d.digits += text[i];
    if (fractional) --d.exponent;
    any_digit = true;
    ++i;
  };
  while (i < text.size() && isDigit(text[i])) take_digit(false);
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && isDigit(text[i])) take_digit(true);
  }
  if (!any_digit) return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool negative_exponent = false;
    if (i < text.size() && (text[i] == '-' || text[i] == '+')) negative_exponent = text[i++] == '-';
    if (i == text.size() || !isDigit(text[i])) return std::nullopt;
    long e = 0;
    while (i < text.size() && isDigit(text[i])) {
      if (e < 1'000'000) e = e * 10 + (text[i] - '0');
      ++i;
    }
    d.exponent += negative_exponent ? -e : e;
  }
  if (i != text.size()) return std::nullopt;
  return d;
}

}  // namespace

Stamp Stamp::fromSeconds(double seconds) { return Stamp(std::llround(seconds * 1e9)); }

std::optional<Stamp> Stamp::parseDecimal(std::string_view text) {
  const auto d = splitDecimal(text);
  if (!d) return std::nullopt;
  if (d->digits.empty()) return Stamp(0);
  // In nanoseconds the value is digits * 10^shift.
  const long shift = d->exponent + 9;
  const long length = static_cast<long>(d->digits.size());
  if (shift > kMaxExponent) return std::nullopt;
  const long kept = shift >= 0 ? length : length + shift;  // digits at or above 1 ns
  std::int64_t ns = 0;
  for (long k = 0; k < kept; ++k)
    if (!appendDigit(ns, d->digits[static_cast<std::size_t>(k)] - '0')) return std::nullopt;
  for (long k = 0; k < shift; ++k)
    if (!appendDigit(ns, 0)) return std::nullopt;
  // Round half away from zero on the first digit below a nanosecond.
  const bool round_up = kept >= 0 && kept < length && d->digits[static_cast<std::size_t>(kept)] >= '5';
  if (round_up) {
    if (ns == kMaxNanoseconds) return std::nullopt;
    ++ns;
  }
  return Stamp(d->negative ? -ns : ns);
}

std::string Stamp::toDecimal() const {
  const bool negative = ns_ < 0;
  // Unsigned so that the most negative stamp has a magnitude too.
  const std::uint64_t magnitude = negative ? 0 - static_cast<std::uint64_t>(ns_) : static_cast<std::uint64_t>(ns_);
  const auto per_second = static_cast<std::uint64_t>(kNanosPerSecond);
  // Appended, not operator+: GCC 12 warns falsely on it (-Wrestrict, bug 105651).
  std::string out = negative ? "-" : "";
  out += std::to_string(magnitude / per_second);
  const std::uint64_t fraction = magnitude % per_second;
  if (fraction == 0) return out;
  std::string digits = std::to_string(fraction);
  digits.insert(0, 9 - digits.size(), '0');
  digits.erase(digits.find_last_not_of('0') + 1);
  return out + "." + digits;
}

}  // namespace scanfilter
