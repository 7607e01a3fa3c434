// CLI11 is slow to compile: this is the only file of the services that includes it.
#include "scanfilter/dds/service_cli.hpp"

#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "scanfilter/dds/default_paths.hpp"
#include "scanfilter/dds/metrics_address.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/input_error.hpp"

namespace scanfilter::dds_io {

std::string scanfilterVersion() { return SCANFILTER_VERSION; }

int runLogged(const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    spdlog::error("{}", e.what());
    return 2;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    return 1;
  }
}

ServiceCli::ServiceCli(std::string name, std::string description, std::string default_metrics_address,
                       std::set<std::string> own_sections)
    : name_(std::move(name)),
      description_(std::move(description)),
      default_metrics_address_(std::move(default_metrics_address)),
      own_sections_(std::move(own_sections)) {}

std::optional<int> ServiceCli::parse(int argc, char** argv) {
  // Usage names the program as it was run: scanfilter-jump-filter where installed, jump_filter in the build tree.
  const std::string program = argc > 0 ? std::filesystem::path(argv[0]).filename().string() : name_;
  CLI::App app{description_, program};
  // Bad arguments: one line (what and which), no usage dump.
  app.failure_message([](const CLI::App*, const CLI::Error& e) { return std::string(e.what()) + " (see --help)\n"; });
  app.set_version_flag("--version", name_ + " (scanfilter " + scanfilterVersion() + ")");
  std::string config_path = defaultConfigDir() + "/" + name_ + ".yaml";
  std::string log_level;
  std::optional<int> domain;
  std::optional<std::string> ns, metrics;
  // The default file is the documented one, wherever this binary reads it from.
  app.add_option("--config", config_path, "service config YAML, every key documented in the default")
      ->capture_default_str();
  app.add_option("--log-level", log_level, "overrides service.log_level: trace, debug, info, warn, error, off")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));
  app.add_option("--domain", domain, "overrides service.domain_id")->check(CLI::Range(0, kMaxDomainId));
  app.add_option("--namespace", ns, "overrides service.namespace (topics rt/<ns>/...)");
  app.add_option("--metrics-address", metrics, "overrides service.metrics_address (host:port)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    config_ = loadServiceConfig(config_path, default_metrics_address_, own_sections_);
  } catch (const InputError& e) {
    std::cerr << name_ << ": error: " << e.what() << "\n";
    return 2;
  }
  ServiceSettings& s = config_.service;
  if (!log_level.empty()) s.log_level = log_level;
  if (domain) s.participant.domain_id = *domain;
  if (ns) {
    if (const auto problem = topicNamespaceProblem(*ns)) {
      std::cerr << name_ << ": error: --namespace: " << *problem << "\n";
      return 2;
    }
    s.topic_namespace = *ns;
  }
  if (metrics) {
    if (const auto problem = metricsAddressProblem(*metrics)) {
      std::cerr << name_ << ": error: --metrics-address: " << *problem << "\n";
      return 2;
    }
    s.metrics_address = *metrics;
  }
  s.participant.name = "scanfilter_" + name_;
  spdlog::set_level(spdlog::level::from_str(s.log_level));
  spdlog::set_pattern("[%Y-%m-%d %H:%M:%S.%e] [" + name_ + "] [%l] %v");
  return std::nullopt;
}

}  // namespace scanfilter::dds_io
