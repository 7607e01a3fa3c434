#include "scanfilter/dds/service_runtime.hpp"

#include <spdlog/spdlog.h>

#include "scanfilter/dds/progress_heartbeat.hpp"
#include "scanfilter/dds/service_cli.hpp"
#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/topic_names.hpp"

namespace scanfilter::dds_io {

namespace {
// The process and matched-endpoint gauges need no finer resolution than this.
constexpr auto kGaugePeriod = std::chrono::seconds(1);

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t k = 0; k < items.size(); ++k) out += (k == 0 ? "" : " and ") + items[k];
  return out.empty() ? "nothing" : out;
}
}  // namespace

ServiceRuntime::ServiceRuntime(const ServiceConfigFile& config, const std::string& name)
    : config_(config),
      metrics_(name, config.service.metrics_address, scanfilterVersion()),
      participant_(config.service.participant) {}

std::string ServiceRuntime::topic(const std::string& name) const { return rosTopic(config_.service.topic_namespace, name); }

void ServiceRuntime::reportMatched(const std::string& endpoint, const std::string& topic, std::function<int()> matched) {
  watched_.push_back({endpoint, topic, std::move(matched)});
}

void ServiceRuntime::refreshGauges() {
  metrics_.updateProcessStats();
  for (const auto& w : watched_) metrics_.matched(w.endpoint, w.topic, w.matched());
}

void ServiceRuntime::logStarted() const {
  std::vector<std::string> reads, writes;
  for (const auto& w : watched_) (w.endpoint == "reader" ? reads : writes).push_back(w.topic);
  // Security on is said: without it, a secured run looks exactly like an open one.
  const std::string& enclave = config_.service.participant.security.enclave;
  const std::string started = fmt::format("started: domain {}, {} -> {}, metrics http://{}/metrics{}",
                                          config_.service.participant.domain_id, joined(reads), joined(writes),
                                          metrics_.address(),
                                          enclave.empty() ? "" : ", DDS Security on (enclave " + enclave + ")");
  spdlog::info("{}", started);
  notifier_.ready(started);
}

void ServiceRuntime::runUntilStopped(std::chrono::milliseconds period, const std::function<void()>& each_period) {
  logStarted();
  auto last_refresh = std::chrono::steady_clock::now() - kGaugePeriod;
  ProgressHeartbeat heartbeat("the service loop");  // a stuck each_period stops the watchdog's pings
  do {
    heartbeat.beat();
    if (each_period) each_period();
    if (std::chrono::steady_clock::now() - last_refresh >= kGaugePeriod) {
      refreshGauges();
      last_refresh = std::chrono::steady_clock::now();
    }
    heartbeat.idle();
  } while (!ShutdownSignal::waitFor(period));
  notifier_.stopping();
}

int runService(int argc, char** argv, const ServiceDescription& description,
               const std::function<int(ServiceRuntime&)>& body) {
  ServiceCli cli(description.name, description.summary, description.default_metrics_address,
                 description.own_sections);
  if (const auto exit_code = cli.parse(argc, argv)) return *exit_code;
  return runLogged([&] {
    ShutdownSignal::install();
    ServiceRuntime runtime(cli.config(), description.name);
    const int code = body(runtime);
    runtime.notifier().stopping();
    spdlog::info("stopped");
    return code;
  });
}

}  // namespace scanfilter::dds_io
