// service.discovery: what the YAML section turns into in the participant's
// QoS, and the errors a bad address gets (file, line, key, value).
#include <cstdlib>
#include <string>

#include <fastdds/rtps/attributes/ServerAttributes.h>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <gtest/gtest.h>

#include "scanfilter/dds/discovery_settings.hpp"
#include "scanfilter/input_error.hpp"

namespace scanfilter::dds_io {
namespace {

using eprosima::fastdds::dds::DomainParticipantQos;
using eprosima::fastrtps::rtps::DiscoveryProtocol;
using eprosima::fastrtps::rtps::IPLocator;

DiscoverySettings parse(const std::string& yaml) {
  const YAML::Node root = parseYaml(yaml, "svc.yaml");
  YamlSection service(root, "service", "svc.yaml");
  DiscoverySettings settings = readDiscoverySettings(service);
  service.rejectUnknownKeys();  // `discovery` was marked as read
  return settings;
}

// The error message of parsing `yaml`, empty if it parsed.
std::string errorOf(const std::string& yaml) {
  try {
    parse(yaml);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string addressOf(const eprosima::fastrtps::rtps::Locator_t& locator) { return IPLocator::toIPv4string(locator); }

TEST(DiscoverySettings, AbsentLeavesTheProfileAlone) {
  const DiscoverySettings s = parse("service: {}\n");
  EXPECT_FALSE(s.configured);
  DomainParticipantQos qos;
  const DomainParticipantQos before = qos;
  applyDiscovery(s, qos);
  EXPECT_TRUE(qos == before);
  EXPECT_FALSE(usesDiscoveryServer(qos));
}

// The interfaces must be this host's: 127.0.0.1, with peers elsewhere in 127/8
// (the three-host test covers real other hosts).
TEST(DiscoverySettings, PeersBecomeInitialPeersWithThisHostsOwnAddress) {
  const DiscoverySettings s = parse("service:\n  discovery: {interfaces: [127.0.0.1], peers: [127.0.0.2, 127.0.0.3]}\n");
  DomainParticipantQos qos;
  applyDiscovery(s, qos);
  const auto& builtin = qos.wire_protocol().builtin;
  EXPECT_EQ(builtin.discovery_config.discoveryProtocol, DiscoveryProtocol::SIMPLE);
  std::vector<std::string> peers;
  for (const auto& l : builtin.initialPeersList) peers.push_back(addressOf(l));
  EXPECT_EQ(peers, (std::vector<std::string>{"127.0.0.1", "127.0.0.2", "127.0.0.3"}));
  ASSERT_EQ(builtin.metatrafficUnicastLocatorList.size(), 1u);
  EXPECT_EQ(addressOf(*builtin.metatrafficUnicastLocatorList.begin()), "127.0.0.1");
  EXPECT_TRUE(builtin.metatrafficMulticastLocatorList.empty());  // no multicast discovery
  EXPECT_FALSE(qos.transport().use_builtin_transports);
  ASSERT_EQ(qos.transport().user_transports.size(), 2u);  // shared memory, then UDPv4
  const auto udp = std::dynamic_pointer_cast<eprosima::fastdds::rtps::UDPv4TransportDescriptor>(
      qos.transport().user_transports.back());
  ASSERT_NE(udp, nullptr);
  EXPECT_EQ(udp->interfaceWhiteList, (std::vector<std::string>{"127.0.0.1"}));
  EXPECT_FALSE(usesDiscoveryServer(qos));
}

TEST(DiscoverySettings, ServersMakeAClientWithTheIdsGuidPrefixes) {
  const DiscoverySettings s =
      parse("service:\n  discovery:\n    interfaces: [127.0.0.1]\n    servers: [\"127.0.0.2:11811\", \"127.0.0.3\", \"\", "
            "\"127.0.0.4:14520\"]\n    shared_memory: false\n");
  DomainParticipantQos qos;
  applyDiscovery(s, qos);
  const auto& config = qos.wire_protocol().builtin.discovery_config;
  EXPECT_EQ(config.discoveryProtocol, DiscoveryProtocol::CLIENT);
  EXPECT_TRUE(usesDiscoveryServer(qos));
  // What ROS_DISCOVERY_SERVER would give for the same list.
  eprosima::fastdds::rtps::RemoteServerList_t expected;
  ASSERT_TRUE(eprosima::fastdds::rtps::load_environment_server_info("127.0.0.2:11811;127.0.0.3;;127.0.0.4:14520", expected));
  EXPECT_EQ(config.m_DiscoveryServers, expected);
  EXPECT_EQ(qos.transport().user_transports.size(), 1u);  // UDP only
}

TEST(DiscoverySettings, RosDiscoveryServerMakesASimpleParticipantAClient) {
  // Fast DDS keeps the variable's last value even once it is unset: the tests
  // that need it unset come before this one (ctest runs each in a process of
  // its own anyway).
  ::setenv("ROS_DISCOVERY_SERVER", "127.0.0.1:11811", 1);
  DomainParticipantQos qos;
  applyDiscovery(parse("service: {discovery: {interfaces: [127.0.0.1]}}\n"), qos);
  EXPECT_TRUE(usesDiscoveryServer(qos));
  ::unsetenv("ROS_DISCOVERY_SERVER");
}

TEST(DiscoverySettings, ErrorsNameFileLineKeyAndValue) {
  EXPECT_EQ(errorOf("service:\n  discovery:\n    peers:\n      - 10.0.1.2\n      - 10.0.1.300\n"),
            "svc.yaml:5: service.discovery.peers: expected another host's IPv4 address, e.g. 10.0.1.2, got \"10.0.1.300\"");
  EXPECT_EQ(errorOf("service:\n  discovery:\n    interfaces: [robot.local]\n"),
            "svc.yaml:3: service.discovery.interfaces: expected this host's IPv4 address, e.g. 10.0.1.1, got \"robot.local\"");
  EXPECT_EQ(errorOf("service:\n  discovery:\n    servers: [\"127.0.0.2:99999\"]\n"),
            "svc.yaml:3: service.discovery.servers: expected ADDRESS:PORT (IPv4, port 1-65535) or \"\", got \"127.0.0.2:99999\"");
  // The limited broadcast address is no interface's own.
  EXPECT_NE(errorOf("service:\n  discovery:\n    interfaces:\n      - 127.0.0.1\n      - 255.255.255.255\n")
                .find("svc.yaml:5: service.discovery.interfaces: expected an address of this host (127.0.0.1"),
            std::string::npos);
  EXPECT_EQ(errorOf("service:\n  discovery:\n    peers: 10.0.1.2\n"),
            "svc.yaml:3: service.discovery.peers: expected a list like [10.0.1.2]");
  EXPECT_EQ(errorOf("service:\n  discovery:\n    peer: [10.0.1.2]\n"),
            "svc.yaml:3: service.discovery.peer: unknown key (did you mean peers?)");
}

TEST(DiscoverySettings, CombinationsThatCannotWorkAreRejected) {
  EXPECT_NE(errorOf("service:\n  discovery: {peers: [127.0.0.2], servers: [\"127.0.0.3\"]}\n")
                .find("either peers (unicast initial peers) or servers (Discovery Server), not both"),
            std::string::npos);
  EXPECT_NE(errorOf("service:\n  discovery: {peers: [10.0.1.2]}\n")
                .find("peer 10.0.1.2 cannot be reached from loopback interfaces"),
            std::string::npos);
  EXPECT_NE(errorOf("service:\n  discovery: {interfaces: []}\n").find("expected at least one address"), std::string::npos);
}

}  // namespace
}  // namespace scanfilter::dds_io
