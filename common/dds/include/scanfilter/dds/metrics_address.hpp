#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace scanfilter::dds_io {

// What is wrong with a metrics address (service.metrics_address,
// --metrics-address), or nothing: it must be host:port, the host an IPv4
// address or a host name, the port 0-65535 (0: any free one, for a program
// whose metrics nobody scrapes, such as the recorder). The HTTP server
// (civetweb) reads a bare port as every interface, and anything else it
// cannot bind as "null context", naming neither the address nor the
// setting: so the address is checked before the service starts.
std::optional<std::string> metricsAddressProblem(std::string_view address);

}  // namespace scanfilter::dds_io
