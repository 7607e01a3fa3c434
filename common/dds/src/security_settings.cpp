#include "scanfilter/dds/security_settings.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace scanfilter::dds_io {

namespace {

using eprosima::fastrtps::rtps::DiscoveryProtocol_t;

// Fast DDS's own participant property names for its builtin plugins.
constexpr const char* kAuthPlugin = "dds.sec.auth.plugin";
constexpr const char* kAuthPrefix = "dds.sec.auth.builtin.PKI-DH.";
constexpr const char* kAccessPlugin = "dds.sec.access.plugin";
constexpr const char* kAccessPrefix = "dds.sec.access.builtin.Access-Permissions.";
constexpr const char* kCryptoPlugin = "dds.sec.crypto.plugin";

// The environment variable with which Fast DDS turns a participant into a
// Discovery Server client (the same one ROS 2 uses).
constexpr const char* kDiscoveryServerEnv = "ROS_DISCOVERY_SERVER";

std::string fileUri(const std::string& enclave, const char* file) {
  return "file://" + (std::filesystem::absolute(enclave) / file).lexically_normal().string();
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

// Where a Discovery Server is configured, if anywhere: Fast DDS 2.9.1's
// Discovery Server does not support DDS Security (that came with 2.10).
std::string discoveryServerSource(const eprosima::fastdds::dds::DomainParticipantQos& qos) {
  switch (qos.wire_protocol().builtin.discovery_config.discoveryProtocol) {
    case DiscoveryProtocol_t::CLIENT: return "the participant is a Discovery Server CLIENT";
    case DiscoveryProtocol_t::SUPER_CLIENT: return "the participant is a Discovery Server SUPER_CLIENT";
    case DiscoveryProtocol_t::SERVER: return "the participant is a Discovery SERVER";
    case DiscoveryProtocol_t::BACKUP: return "the participant is a Discovery Server BACKUP";
    default: break;
  }
  const char* env = std::getenv(kDiscoveryServerEnv);
  if (env != nullptr && *env != '\0') return std::string(kDiscoveryServerEnv) + "=" + env + " is set";
  return "";
}

}  // namespace

std::vector<std::string> missingEnclaveFiles(const std::string& enclave) {
  std::vector<std::string> missing;
  for (const char* file : {kIdentityCaFile, kCertificateFile, kPrivateKeyFile, kPermissionsCaFile, kGovernanceFile,
                           kPermissionsFile}) {
    const auto path = std::filesystem::path(enclave) / file;
    if (!std::ifstream(path).good()) missing.push_back(path.string());
  }
  return missing;
}

SecuritySettings readSecuritySettings(YamlSection& service, const std::string& config_directory) {
  service.take("security");
  YamlSection section(service.node(), "security", service.file(), service.path());
  SecuritySettings s;
  section.read("enclave", s.enclave);
  section.rejectUnknownKeys();
  if (!s.enabled()) return s;
  if (std::filesystem::path(s.enclave).is_relative())
    s.enclave = (std::filesystem::path(config_directory) / s.enclave).lexically_normal().string();
  if (!std::filesystem::is_directory(s.enclave))
    section.fail("enclave", "no such directory: " + s.enclave +
                                " (scanfilter-make-keystore, deploy/security/make-keystore.sh in the source tree, "
                                "makes one)");
  if (const auto missing = missingEnclaveFiles(s.enclave); !missing.empty())
    section.fail("enclave", "the enclave lacks " + joined(missing));
  return s;
}

void applySecurity(const SecuritySettings& settings, eprosima::fastdds::dds::DomainParticipantQos& qos) {
  if (!settings.enabled()) return;
  if (const auto missing = missingEnclaveFiles(settings.enclave); !missing.empty())
    throw std::runtime_error("DDS Security: the enclave " + settings.enclave + " lacks " + joined(missing));
  if (const std::string server = discoveryServerSource(qos); !server.empty())
    throw std::runtime_error("DDS Security and a Discovery Server are both configured (" + server +
                             "), but Fast DDS 2.9 cannot secure Discovery Server traffic: secured deployments "
                             "use unicast peers (docs/operations.md, DDS Security)");
  auto& properties = qos.properties().properties();
  const std::string& dir = settings.enclave;
  properties.emplace_back(kAuthPlugin, "builtin.PKI-DH");
  properties.emplace_back(std::string(kAuthPrefix) + "identity_ca", fileUri(dir, kIdentityCaFile));
  properties.emplace_back(std::string(kAuthPrefix) + "identity_certificate", fileUri(dir, kCertificateFile));
  properties.emplace_back(std::string(kAuthPrefix) + "private_key", fileUri(dir, kPrivateKeyFile));
  properties.emplace_back(kAccessPlugin, "builtin.Access-Permissions");
  properties.emplace_back(std::string(kAccessPrefix) + "permissions_ca", fileUri(dir, kPermissionsCaFile));
  properties.emplace_back(std::string(kAccessPrefix) + "governance", fileUri(dir, kGovernanceFile));
  properties.emplace_back(std::string(kAccessPrefix) + "permissions", fileUri(dir, kPermissionsFile));
  properties.emplace_back(kCryptoPlugin, "builtin.AES-GCM-GMAC");
}

std::string securityFailureHint(const SecuritySettings& settings) {
  if (!settings.enabled()) return "";
  return " (DDS Security is on with enclave " + settings.enclave +
         ": Fast DDS's log above says which certificate, key or signed document it rejected, e.g. one "
         "from another CA, expired, or permissions without a grant for this certificate or domain)";
}

}  // namespace scanfilter::dds_io
