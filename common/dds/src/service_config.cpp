#include "scanfilter/dds/service_config.hpp"

#include <filesystem>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/metrics_address.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/input_error.hpp"
#include "scanfilter/yaml_section.hpp"

namespace scanfilter::dds_io {

std::string ServiceConfigFile::resolvePath(const std::string& p) const {
  if (p.empty() || std::filesystem::path(p).is_absolute()) return p;
  return (std::filesystem::path(directory) / p).lexically_normal().string();
}

ServiceConfigFile loadServiceConfig(const std::string& path, const std::string& default_metrics_address,
                                    const std::set<std::string>& own_sections) {
  ServiceConfigFile file;
  file.path = path;
  file.directory = std::filesystem::absolute(path).parent_path().string();
  file.root = loadYamlFile(path);
  if (!file.root.IsMap()) throw InputError(path, 1, "", "expected a mapping at the top level");
  for (const auto& entry : file.root) {
    const auto key = keyText(entry.first, path);
    if (key != "service" && !own_sections.count(key))
      throw InputError(path, static_cast<std::size_t>(entry.first.Mark().line) + 1, key, "unknown section");
  }
  ServiceSettings& s = file.service;
  s.metrics_address = default_metrics_address;
  YamlSection section(file.root, "service", path);
  section.read("domain_id", s.participant.domain_id);
  section.read("namespace", s.topic_namespace);
  std::string profiles = "fastdds-loopback.xml";
  section.read("profiles_file", profiles);
  s.participant.profiles_file = file.resolvePath(profiles);
  section.read("participant_profile", s.participant.profile);
  section.read("metrics_address", s.metrics_address);
  section.readChoice("log_level", s.log_level, {"trace", "debug", "info", "warn", "error", "off"});
  section.read("queue_depth", s.stream.queue_depth);
  section.read("max_blocking_s", s.stream.max_blocking_s);
  s.participant.discovery = readDiscoverySettings(section);
  section.read("required_readers", s.stream.required_readers);
  section.requireRange("required_readers", s.stream.required_readers, 0, 1000, "an integer 0-1000");
  section.requireRange("domain_id", s.participant.domain_id, 0, kMaxDomainId, "a DDS domain id 0-232");
  section.requireRange("queue_depth", s.stream.queue_depth, 1, kMaxQueueDepth, "an integer 1-100000");
  section.requireRange("max_blocking_s", s.stream.max_blocking_s, 0.001, 3600, "0.001-3600 (s)");
  if (const auto problem = topicNamespaceProblem(s.topic_namespace)) section.fail("namespace", *problem);
  if (const auto problem = metricsAddressProblem(s.metrics_address)) section.fail("metrics_address", *problem);
  section.requireFile("profiles_file", s.participant.profiles_file);
  s.participant.security = readSecuritySettings(section, file.directory);
  section.rejectUnknownKeys();
  return file;
}

FilterConfig loadStageFilterConfig(const ServiceConfigFile& config) {
  YamlSection section(config.root, "filter", config.path);
  std::string filter_file = "filter.yaml";
  section.read("config", filter_file);
  section.rejectUnknownKeys();
  const std::string path = config.resolvePath(filter_file);
  section.requireFile("config", path);
  return loadFilterConfig(path);
}

}  // namespace scanfilter::dds_io
