#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/service_config.hpp"
#include "scanfilter/dds/service_metrics.hpp"
#include "scanfilter/dds/systemd_notifier.hpp"

namespace scanfilter::dds_io {

// What tells one service from another on the command line and in metrics.
struct ServiceDescription {
  std::string name;                      // "jump_filter": log prefix, metrics label, config file name
  std::string summary;                   // the first line of --help
  std::string default_metrics_address;   // host:port
  std::set<std::string> own_sections;    // config sections besides `service`
};

// What every service shares once its command line and config are read:
// SIGINT/SIGTERM handling, the Prometheus endpoint, the DDS participant, and
// the loop that keeps the process and matched-endpoint gauges current until
// a signal asks the service to stop. A service's main is its description and
// a body that creates its endpoints and then runs this loop.
class ServiceRuntime {
 public:
  ServiceRuntime(const ServiceConfigFile& config, const std::string& name);
  ServiceRuntime(const ServiceRuntime&) = delete;
  ServiceRuntime& operator=(const ServiceRuntime&) = delete;

  const ServiceConfigFile& config() const { return config_; }
  const ServiceSettings& settings() const { return config_.service; }
  ServiceMetrics& metrics() { return metrics_; }
  DdsParticipant& participant() { return participant_; }
  const SystemdNotifier& notifier() const { return notifier_; }
  // rt/<namespace>/<name>
  std::string topic(const std::string& name) const;

  // An endpoint whose matched peers scanfilter_dds_matched reports
  // (endpoint "reader" or "writer").
  void reportMatched(const std::string& endpoint, const std::string& topic, std::function<int()> matched);

  // Logs what the service reads and writes, then every `period` calls
  // `each_period` (the process and matched gauges are refreshed about once a
  // second), until SIGINT/SIGTERM.
  void runUntilStopped(std::chrono::milliseconds period = std::chrono::seconds(1),
                       const std::function<void()>& each_period = {});
  // The process and matched gauges now (for services that run their own loop).
  void refreshGauges();
  // "started: domain D, rt/a -> rt/b and rt/c, metrics http://…"; also
  // tells systemd the service is ready (its endpoints exist by then).
  void logStarted() const;

 private:
  struct Watched {
    std::string endpoint;
    std::string topic;
    std::function<int()> matched;
  };

  SystemdNotifier notifier_;  // first: its watchdog pings while the rest starts
  const ServiceConfigFile& config_;
  ServiceMetrics metrics_;
  DdsParticipant participant_;
  std::vector<Watched> watched_;
};

// Parses the command line and config (--help, --version and bad input end it
// here), installs the signal handlers, then runs body(runtime). Exit codes:
// the body's, 2 for bad input (a config value, a file), 1 for anything else,
// both logged.
int runService(int argc, char** argv, const ServiceDescription& description,
               const std::function<int(ServiceRuntime&)>& body);

}  // namespace scanfilter::dds_io
