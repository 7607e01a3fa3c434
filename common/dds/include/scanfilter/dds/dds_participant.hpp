#pragma once
#include <string>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include "scanfilter/dds/discovery_settings.hpp"
#include "scanfilter/dds/security_settings.hpp"

namespace scanfilter::dds_io {

// The RTPS port mapping (PB 7400 + DG 250 × domain) leaves room for domains 0-232.
inline constexpr int kMaxDomainId = 232;

// Where a service's participant lives and how it talks: the domain and a
// Fast DDS XML profile (deploy/fastdds-loopback.xml by default: localhost only).
struct ParticipantSettings {
  int domain_id = 0;  // 0 to kMaxDomainId
  std::string profiles_file;
  std::string profile = "scanfilter_loopback";
  std::string name = "scanfilter";
  DiscoverySettings discovery;  // service.discovery: other hosts (replaces the profile's transports)
  SecuritySettings security;    // off unless service.security.enclave is set
};

// One DomainParticipant with one publisher and one subscriber, created from
// the XML profile and deleted, with everything in it, on destruction.
class DdsParticipant {
 public:
  explicit DdsParticipant(const ParticipantSettings& settings);  // throws std::runtime_error
  ~DdsParticipant();
  DdsParticipant(const DdsParticipant&) = delete;
  DdsParticipant& operator=(const DdsParticipant&) = delete;

  // The topic of that name, created (and its type registered) on first use.
  eprosima::fastdds::dds::Topic* topic(const std::string& name, eprosima::fastdds::dds::TypeSupport type);

  eprosima::fastdds::dds::DomainParticipant* participant() const { return participant_; }
  eprosima::fastdds::dds::Publisher* publisher() const { return publisher_; }
  eprosima::fastdds::dds::Subscriber* subscriber() const { return subscriber_; }

 private:
  eprosima::fastdds::dds::DomainParticipant* participant_ = nullptr;
  eprosima::fastdds::dds::Publisher* publisher_ = nullptr;
  eprosima::fastdds::dds::Subscriber* subscriber_ = nullptr;
};

}  // namespace scanfilter::dds_io
