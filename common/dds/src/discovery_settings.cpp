#include "scanfilter/dds/discovery_settings.hpp"

#include <arpa/inet.h>
#include <ifaddrs.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <memory>

#include <fastdds/rtps/attributes/ServerAttributes.h>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastdds/rtps/transport/shared_mem/SharedMemTransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include "scanfilter/input_error.hpp"

namespace scanfilter::dds_io {

using eprosima::fastrtps::rtps::DiscoveryProtocol;
using eprosima::fastrtps::rtps::IPLocator;
using eprosima::fastrtps::rtps::Locator_t;

namespace {

// The port `fastdds discovery` listens on unless given -p (and ROS_DISCOVERY_SERVER's default).
constexpr std::uint16_t kDefaultServerPort = eprosima::fastdds::rtps::DEFAULT_ROS2_SERVER_PORT;
// Server ids are one octet of the GUID prefix (`fastdds discovery -i 0-255`).
constexpr int kMaxServerId = 255;
// Participants per host a unicast peer is probed for (one port pair each);
// the loopback profile's value: at Fast DDS's default of 4 a publisher failed
// to match six local subscribers (deploy/fastdds-loopback.xml, docs/dds.md).
constexpr std::uint32_t kMaxInitialPeersRange = 32;

std::size_t lineOf(const YAML::Node& node) {
  return node.Mark().line >= 0 ? static_cast<std::size_t>(node.Mark().line) + 1 : 0;
}

// A dotted-quad IPv4 address (no host names: what a participant binds to or
// sends to must not depend on a resolver at start-up).
bool isIpv4(const std::string& text) {
  in_addr parsed{};
  return inet_pton(AF_INET, text.c_str(), &parsed) == 1;
}

bool isLoopback(const std::string& ipv4) { return ipv4.rfind("127.", 0) == 0; }

// This host's IPv4 addresses. UDP bound to any other one would not come up
// (Fast DDS logs an error and carries on with a participant nobody reaches).
std::vector<std::string> hostAddresses() {
  std::vector<std::string> out;
  ifaddrs* list = nullptr;
  if (getifaddrs(&list) != 0) return out;
  for (const ifaddrs* a = list; a != nullptr; a = a->ifa_next) {
    if (a->ifa_addr == nullptr || a->ifa_addr->sa_family != AF_INET) continue;
    char text[INET_ADDRSTRLEN] = {};
    if (inet_ntop(AF_INET, &reinterpret_cast<const sockaddr_in*>(a->ifa_addr)->sin_addr, text, sizeof text))
      out.emplace_back(text);
  }
  freeifaddrs(list);
  return out;
}

class DiscoveryReader {
 public:
  explicit DiscoveryReader(YamlSection& service)
      : section_(service.node(), "discovery", service.file(), service.path()) {
    service.take("discovery");
  }

  DiscoverySettings read() {
    DiscoverySettings s;
    s.configured = section_.present();
    if (!s.configured) return s;
    readAddresses("interfaces", s.interfaces, "this host's IPv4 address", "10.0.1.1");
    requireOwnAddresses(s.interfaces);
    readAddresses("peers", s.peers, "another host's IPv4 address", "10.0.1.2");
    readServers(s.servers);
    section_.read("shared_memory", s.shared_memory);
    section_.rejectUnknownKeys();
    check(s);
    return s;
  }

 private:
  // A list of addresses, each one checked where it is written.
  void readAddresses(const char* key, std::vector<std::string>& out, const std::string& what, const std::string& example) {
    const YAML::Node list = section_.take(key);
    if (!list) return;
    if (!list.IsSequence()) section_.fail(key, "expected a list like [" + example + "]");
    out.clear();
    for (const auto& item : list) {
      const std::string text = item.IsScalar() ? item.Scalar() : "a non-scalar";
      if (!isIpv4(text) || text == "0.0.0.0")
        failAt(item, key, "expected " + what + ", e.g. " + example + ", got \"" + text + "\"");
      out.push_back(text);
    }
  }

  // Each interface is an address of the host reading the config (where the service runs).
  void requireOwnAddresses(const std::vector<std::string>& interfaces) {
    const std::vector<std::string> own = hostAddresses();
    const YAML::Node list = section_.node()["interfaces"];
    for (std::size_t i = 0; i < interfaces.size(); ++i) {
      if (std::find(own.begin(), own.end(), interfaces[i]) != own.end()) continue;
      std::string known;
      for (const auto& a : own) known += (known.empty() ? "" : ", ") + a;
      const YAML::Node at = list ? list[i] : section_.node();
      failAt(at, "interfaces", "expected an address of this host (" + known + "), got \"" + interfaces[i] + "\"");
    }
  }

  // "ADDRESS:PORT" or "ADDRESS" (port 11811); the position is the server id,
  // as in ROS_DISCOVERY_SERVER, and "" skips an id.
  void readServers(std::vector<DiscoveryServer>& out) {
    const YAML::Node list = section_.take("servers");
    if (!list) return;
    if (!list.IsSequence()) section_.fail("servers", "expected a list like [\"10.0.2.1:11811\", \"10.0.3.1:11811\"]");
    int id = 0;
    for (const auto& item : list) {
      const std::string text = item.IsScalar() ? item.Scalar() : "a non-scalar";
      const std::string expected = "expected ADDRESS:PORT (IPv4, port 1-65535) or \"\", got \"" + text + "\"";
      if (id > kMaxServerId) failAt(item, "servers", "at most 256 servers (ids 0-255)");
      if (text.empty()) {
        ++id;
        continue;
      }
      DiscoveryServer server{text, kDefaultServerPort, id++};
      if (const auto colon = text.find(':'); colon != std::string::npos) {
        server.address = text.substr(0, colon);
        const std::string port = text.substr(colon + 1);
        char* end = nullptr;
        const long value = std::strtol(port.c_str(), &end, 10);
        if (port.empty() || *end != '\0' || value < 1 || value > std::numeric_limits<std::uint16_t>::max())
          failAt(item, "servers", expected);
        server.port = static_cast<std::uint16_t>(value);
      }
      if (!isIpv4(server.address) || server.address == "0.0.0.0") failAt(item, "servers", expected);
      out.push_back(server);
    }
    if (out.empty()) section_.fail("servers", "expected at least one server address");
  }

  // Combinations that cannot work, caught before a participant silently finds nobody.
  void check(const DiscoverySettings& s) const {
    if (s.interfaces.empty()) section_.fail("interfaces", "expected at least one address");
    if (!s.peers.empty() && !s.servers.empty())
      section_.fail("servers", "expected either peers (unicast initial peers) or servers (Discovery Server), not both");
    bool only_loopback = true;
    for (const auto& a : s.interfaces) only_loopback = only_loopback && isLoopback(a);
    if (!only_loopback) return;
    for (const auto& p : s.peers)
      if (!isLoopback(p)) section_.fail("peers", "peer " + p + " cannot be reached from loopback interfaces; list this host's address under interfaces");
    for (const auto& v : s.servers)
      if (!isLoopback(v.address))
        section_.fail("servers", "server " + v.address + " cannot be reached from loopback interfaces; list this host's address under interfaces");
  }

  [[noreturn]] void failAt(const YAML::Node& item, const char* key, const std::string& problem) const {
    throw InputError(section_.file(), lineOf(item), section_.path() + "." + key, problem);
  }

  YamlSection section_;
};

Locator_t udpLocator(const std::string& address, std::uint16_t port) {
  Locator_t locator;  // UDPv4 by default
  IPLocator::setIPv4(locator, address);
  locator.port = port;  // 0: Fast DDS picks the domain's well-known ports
  return locator;
}

}  // namespace

DiscoverySettings readDiscoverySettings(YamlSection& service_section) {
  return DiscoveryReader(service_section).read();
}

void applyDiscovery(const DiscoverySettings& settings, eprosima::fastdds::dds::DomainParticipantQos& qos) {
  if (!settings.configured) return;
  using namespace eprosima::fastdds::rtps;
  auto& transport = qos.transport();
  transport.use_builtin_transports = false;
  transport.user_transports.clear();
  if (settings.shared_memory) transport.user_transports.push_back(std::make_shared<SharedMemTransportDescriptor>());
  auto udp = std::make_shared<UDPv4TransportDescriptor>();
  udp->interfaceWhiteList = settings.interfaces;
  udp->maxInitialPeersRange = kMaxInitialPeersRange;
  transport.user_transports.push_back(udp);

  auto& wire = qos.wire_protocol();
  auto& builtin = wire.builtin;
  wire.default_unicast_locator_list.clear();
  builtin.metatrafficUnicastLocatorList.clear();
  builtin.initialPeersList.clear();
  builtin.discovery_config.m_DiscoveryServers.clear();
  // Data locators are left to Fast DDS, which announces one per transport:
  // shared memory (used by the participants on this host) and UDP on the
  // interfaces (by the others). Discovery goes over UDP on the interfaces
  // only; listing them here is also what keeps Fast DDS from adding its
  // multicast discovery locator.
  for (const auto& address : settings.interfaces) builtin.metatrafficUnicastLocatorList.push_back(udpLocator(address, 0));
  if (!settings.servers.empty()) {
    builtin.discovery_config.discoveryProtocol = DiscoveryProtocol::CLIENT;
    for (const auto& server : settings.servers) {
      RemoteServerAttributes remote;
      get_server_client_default_guidPrefix(server.id, remote.guidPrefix);
      remote.metatrafficUnicastLocatorList.push_back(udpLocator(server.address, server.port));
      builtin.discovery_config.m_DiscoveryServers.push_back(remote);
    }
    return;
  }
  builtin.discovery_config.discoveryProtocol = DiscoveryProtocol::SIMPLE;
  // This host's own addresses too: the other participants on it are found
  // the same way as those on the peers.
  for (const auto& address : settings.interfaces) builtin.initialPeersList.push_back(udpLocator(address, 0));
  for (const auto& address : settings.peers) builtin.initialPeersList.push_back(udpLocator(address, 0));
}

bool usesDiscoveryServer(const eprosima::fastdds::dds::DomainParticipantQos& qos) {
  switch (qos.wire_protocol().builtin.discovery_config.discoveryProtocol) {
    case DiscoveryProtocol::CLIENT:
    case DiscoveryProtocol::SUPER_CLIENT:
    case DiscoveryProtocol::SERVER:
    case DiscoveryProtocol::BACKUP:
      return true;
    case DiscoveryProtocol::SIMPLE:
      return !eprosima::fastdds::rtps::ros_discovery_server_env().empty();
    default:
      return false;
  }
}

}  // namespace scanfilter::dds_io
