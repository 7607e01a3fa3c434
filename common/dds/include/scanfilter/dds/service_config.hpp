#pragma once
#include <set>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/filter_config.hpp"

namespace scanfilter::dds_io {

// The `service:` section every service's YAML has (config/*.yaml document it).
struct ServiceSettings {
  ParticipantSettings participant;
  std::string topic_namespace;  // topics are rt/<namespace>/<name>
  std::string metrics_address;  // host:port of the Prometheus endpoint
  std::string log_level = "info";
  StreamQos stream;
};

// A service's config file: the common section, and the document for the
// service's own sections.
struct ServiceConfigFile {
  std::string path;
  std::string directory;  // relative paths in the file are relative to it
  YAML::Node root;
  ServiceSettings service;

  // Resolves a path written in the file against the file's directory.
  std::string resolvePath(const std::string& p) const;
};

// The filter parameters a filter stage uses: the file named by the config's
// `filter.config` key (config/filter.yaml by default), loaded and validated.
scanfilter::FilterConfig loadStageFilterConfig(const ServiceConfigFile& config);

// Loads `path`, validates `service:` and checks that the top level has no
// keys but `service` and `own_sections`. Throws InputError naming the key.
ServiceConfigFile loadServiceConfig(const std::string& path, const std::string& default_metrics_address,
                                    const std::set<std::string>& own_sections);

}  // namespace scanfilter::dds_io
