#include "scanfilter/dds/service_metrics.hpp"

#include <unistd.h>

#include <ctime>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace scanfilter::dds_io {

using namespace prometheus;

namespace {

double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long pages_total = 0, pages_resident = 0;
  statm >> pages_total >> pages_resident;
  return static_cast<double>(pages_resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

// The HTTP server, or an error that names the address: civetweb's own says
// only "null context when constructing CivetServer".
std::unique_ptr<Exposer> startExposer(const std::string& address) {
  try {
    return std::make_unique<Exposer>(address);
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot serve metrics on " + address + " (service.metrics_address, --metrics-address): " +
                             e.what() + " Is another process using that port?");
  }
}

}  // namespace

// Microseconds to tens of milliseconds: a filter step takes tens of µs, a
// DDS hop hundreds of µs, a slow pipeline tens of ms.
Histogram::BucketBoundaries ServiceMetrics::latencyBuckets() {
  return {1e-5, 2.5e-5, 5e-5, 1e-4, 2.5e-4, 5e-4, 1e-3, 2.5e-3, 5e-3, 1e-2, 2.5e-2, 5e-2, 1e-1};
}

ServiceMetrics::ServiceMetrics(const std::string& service, const std::string& address, const std::string& version)
    : service_(service),
      address_(address),
      exposer_(startExposer(address)),
      registry_(std::make_shared<Registry>()),
      received_(BuildCounter().Name("scanfilter_scans_received_total").Help("Scans received").Register(*registry_).Add({{"service", service}})),
      published_(BuildCounter().Name("scanfilter_scans_published_total").Help("Scans published").Register(*registry_).Add({{"service", service}})),
      removed_(BuildCounter().Name("scanfilter_points_removed_total").Help("Points removed, by reason").Register(*registry_)),
      rejected_(BuildCounter().Name("scanfilter_samples_rejected_total").Help("Samples dropped as invalid, by reason").Register(*registry_)),
      restored_(BuildCounter().Name("scanfilter_points_restored_total").Help("Jump points restored by the persistence rescue").Register(*registry_).Add({{"service", service}})),
      processing_(BuildHistogram().Name("scanfilter_processing_seconds").Help("Time to filter one scan").Register(*registry_)
                      .Add({{"service", service}}, latencyBuckets())),
      latency_(BuildHistogram().Name("scanfilter_end_to_end_latency_seconds").Help("From ingest publishing a scan to this service publishing it")
                   .Register(*registry_).Add({{"service", service}}, latencyBuckets())),
      hop_(BuildHistogram().Name("scanfilter_hop_latency_seconds").Help("From the previous stage publishing a scan to this service receiving it")
               .Register(*registry_).Add({{"service", service}}, latencyBuckets())),
      matched_(BuildGauge().Name("scanfilter_dds_matched").Help("Matched DDS endpoints per local reader/writer").Register(*registry_)),
      upstream_alive_(BuildGauge().Name("scanfilter_upstream_alive").Help("1 while a writer of the stage topic read is matched (DDS discovery: gone when it leaves or its participant lease runs out), else 0").Register(*registry_)),
      cpu_seconds_(BuildGauge().Name("scanfilter_process_cpu_seconds_total").Help("CPU time used by the process").Register(*registry_).Add({{"service", service}})),
      resident_bytes_(BuildGauge().Name("scanfilter_process_resident_memory_bytes").Help("Resident memory of the process").Register(*registry_).Add({{"service", service}})) {
  BuildGauge().Name("scanfilter_build_info").Help("Build information").Register(*registry_).Add({{"service", service}, {"version", version}}).Set(1);
  exposer_->RegisterCollectable(registry_);
}

ServiceMetrics::~ServiceMetrics() {
  // Stopping civetweb waits out its 2 s poll quantum, which would break the
  // promise that SIGTERM ends a service within a second. The service is
  // exiting: the exposer (its thread and listening socket) lives on until the
  // process ends. It is kept reachable from a never-destroyed list rather
  // than released into nothing: an object meant to outlive its owner, not a
  // leak (LeakSanitizer reported the released one, docs/reliability.md).
  static std::mutex kept_mutex;
  static auto* kept_until_exit = new std::vector<std::unique_ptr<Exposer>>();
  const std::lock_guard lock(kept_mutex);
  kept_until_exit->push_back(std::move(exposer_));
}

void ServiceMetrics::pointsRemoved(const std::string& reason, double count) {
  removed_.Add({{"service", service_}, {"reason", reason}}).Increment(count);
}

void ServiceMetrics::sampleRejected(const std::string& reason) {
  rejected_.Add({{"service", service_}, {"reason", reason}}).Increment();
}

void ServiceMetrics::matched(const std::string& endpoint, const std::string& topic, int count) {
  matched_.Add({{"service", service_}, {"endpoint", endpoint}, {"topic", topic}}).Set(count);
}

void ServiceMetrics::upstreamAlive(const std::string& topic, bool alive) {
  upstream_alive_.Add({{"service", service_}, {"topic", topic}}).Set(alive ? 1 : 0);
}

void ServiceMetrics::updateProcessStats() {
  cpu_seconds_.Set(static_cast<double>(std::clock()) / CLOCKS_PER_SEC);
  resident_bytes_.Set(residentBytes());
}

}  // namespace scanfilter::dds_io
