#pragma once
#include <functional>
#include <optional>
#include <set>
#include <string>

#include "scanfilter/dds/service_config.hpp"

namespace scanfilter::dds_io {

// What every service's command line has: --help, --version, --config,
// --log-level, and overrides for the domain, the namespace and the metrics
// address. parse() loads and validates the config and sets up logging.
class ServiceCli {
 public:
  ServiceCli(std::string name, std::string description, std::string default_metrics_address,
             std::set<std::string> own_sections);

  // Exit code when the process should stop now (help, version, bad input).
  std::optional<int> parse(int argc, char** argv);
  const ServiceConfigFile& config() const { return config_; }

 private:
  std::string name_;
  std::string description_;
  std::string default_metrics_address_;
  std::set<std::string> own_sections_;
  ServiceConfigFile config_;
};

std::string scanfilterVersion();

// Runs a service's body and turns what escapes it into an exit code: bad
// input (a config value, a file) 2, anything else 1, both logged.
int runLogged(const std::function<int()>& body);

}  // namespace scanfilter::dds_io
