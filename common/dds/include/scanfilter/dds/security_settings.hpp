#pragma once
#include <string>
#include <vector>

#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>

#include "scanfilter/yaml_section.hpp"

namespace scanfilter::dds_io {

// DDS Security for one participant: the enclave directory it authenticates
// with (a keystore's enclaves/<path>, made by deploy/security/make-keystore.sh
// or by ROS 2's sros2). Empty: security off, the shipped default.
struct SecuritySettings {
  std::string enclave;
  bool enabled() const { return !enclave.empty(); }
};

// The files an enclave must hold, in the layout sros2 uses.
inline constexpr const char* kIdentityCaFile = "identity_ca.cert.pem";
inline constexpr const char* kCertificateFile = "cert.pem";
inline constexpr const char* kPrivateKeyFile = "key.pem";
inline constexpr const char* kPermissionsCaFile = "permissions_ca.cert.pem";
inline constexpr const char* kGovernanceFile = "governance.p7s";
inline constexpr const char* kPermissionsFile = "permissions.p7s";

// The enclave's files that are missing or unreadable (empty: all there).
std::vector<std::string> missingEnclaveFiles(const std::string& enclave);

// Reads the `security` subsection of `service` (service.security.enclave;
// a relative path is resolved against `config_directory`) and checks that
// the enclave holds every file. Throws InputError naming the key and the
// missing files.
SecuritySettings readSecuritySettings(YamlSection& service, const std::string& config_directory);

// With security on: checks the enclave (std::runtime_error naming a missing
// file), refuses a Discovery Server setup (Fast DDS 2.9 cannot secure it:
// std::runtime_error saying so), and sets the participant properties that
// switch on authentication (PKI-DH), access control (signed governance and
// permissions) and encryption (AES-GCM-GMAC). Off: leaves `qos` alone.
// Call it after everything else has been applied to the QoS.
void applySecurity(const SecuritySettings& settings, eprosima::fastdds::dds::DomainParticipantQos& qos);

// A hint for a failed participant creation: what to check when security is on.
std::string securityFailureHint(const SecuritySettings& settings);

}  // namespace scanfilter::dds_io
