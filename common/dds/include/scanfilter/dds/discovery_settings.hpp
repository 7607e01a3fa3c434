#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>

#include "scanfilter/yaml_section.hpp"

namespace scanfilter::dds_io {

// One Fast DDS Discovery Server a client registers with. Its GUID prefix
// follows from `id`, as `fastdds discovery -i ID` and ROS_DISCOVERY_SERVER
// (where the id is the position in the list) derive it.
struct DiscoveryServer {
  std::string address;  // IPv4
  std::uint16_t port = 0;
  int id = 0;
};

// How a participant finds the others beyond the XML profile's localhost-only
// setup: the `service.discovery` section (config/scan_ingest.yaml documents
// it). Absent, the profile is used as it is.
struct DiscoverySettings {
  bool configured = false;                         // the section is present
  std::vector<std::string> interfaces{"127.0.0.1"};  // IPv4 addresses of this host to bind UDP to
  std::vector<std::string> peers;                  // unicast initial peers (other hosts' addresses)
  std::vector<DiscoveryServer> servers;            // Discovery Servers (this participant is their client)
  bool shared_memory = true;                       // same-host traffic over shared memory
};

// Reads the `discovery` subsection of the `service` section, validating every
// address; throws InputError naming file, line, key and value.
DiscoverySettings readDiscoverySettings(YamlSection& service_section);

// Replaces the profile's transports and discovery with `settings` (if the
// section was given): SHM plus UDPv4 bound to the interfaces, and either
// unicast initial peers or Discovery Server client mode.
void applyDiscovery(const DiscoverySettings& settings, eprosima::fastdds::dds::DomainParticipantQos& qos);

// Whether a participant created with `qos` discovers through a Discovery
// Server: its discovery protocol is a server's or a client's, or it is SIMPLE
// and ROS_DISCOVERY_SERVER is set (Fast DDS then turns it into a client when
// the participant is created). Call it after the profile and applyDiscovery.
bool usesDiscoveryServer(const eprosima::fastdds::dds::DomainParticipantQos& qos);

}  // namespace scanfilter::dds_io
