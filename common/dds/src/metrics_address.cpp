#include "scanfilter/dds/metrics_address.hpp"

#include <algorithm>
#include <cctype>

namespace scanfilter::dds_io {

namespace {

constexpr long kMaxPort = 65535;
// "65535" has five digits; more cannot be a port (and would overflow).
constexpr std::size_t kMaxPortDigits = 5;

bool isHostCharacter(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '-' || c == '_';
}

bool isPort(std::string_view text) {
  if (text.empty() || text.size() > kMaxPortDigits) return false;
  const auto isDigit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  if (!std::all_of(text.begin(), text.end(), isDigit)) return false;
  const long port = std::stol(std::string(text));
  return port <= kMaxPort;
}

}  // namespace

std::optional<std::string> metricsAddressProblem(std::string_view address) {
  const std::string expected =
      "expected host:port (an IPv4 address or host name, a port 0-65535, 0: any free one; e.g. 127.0.0.1:9471)";
  const std::string got = ", got \"" + std::string(address) + "\"";
  const std::size_t colon = address.rfind(':');
  if (colon == std::string_view::npos) return expected + got;
  const std::string_view host = address.substr(0, colon);
  const std::string_view port = address.substr(colon + 1);
  if (host.empty() || !std::all_of(host.begin(), host.end(), isHostCharacter)) return expected + got;
  if (!isPort(port)) return expected + got;
  return std::nullopt;
}

}  // namespace scanfilter::dds_io
