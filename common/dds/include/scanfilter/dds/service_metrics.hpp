#pragma once
#include <memory>
#include <string>

#include <prometheus/counter.h>
#include <prometheus/exposer.h>
#include <prometheus/family.h>
#include <prometheus/gauge.h>
#include <prometheus/histogram.h>
#include <prometheus/registry.h>

namespace scanfilter::dds_io {

// The Prometheus metrics every service exposes, named by the Prometheus
// conventions (scanfilter_…_total, …_seconds) and labelled with the service.
// Served over HTTP at `address` (host:port, loopback by default).
class ServiceMetrics {
 public:
  ServiceMetrics(const std::string& service, const std::string& address, const std::string& version);
  // Lives as long as the service: see the destructor.
  ~ServiceMetrics();
  ServiceMetrics(const ServiceMetrics&) = delete;
  ServiceMetrics& operator=(const ServiceMetrics&) = delete;

  void scanReceived() { received_.Increment(); }
  void scanPublished() { published_.Increment(); }
  void pointsRemoved(const std::string& reason, double count);
  void sampleRejected(const std::string& reason);
  void pointsRestored(double count) { restored_.Increment(count); }
  void processingTime(double seconds) { processing_.Observe(seconds); }
  void endToEndLatency(double seconds) { latency_.Observe(seconds); }
  void hopLatency(double seconds) { hop_.Observe(seconds); }
  void matched(const std::string& endpoint, const std::string& topic, int count);
  // scanfilter_upstream_alive{service,topic}: 1 while a writer of the stage
  // topic this service reads is matched (DDS discovery), 0 otherwise.
  void upstreamAlive(const std::string& topic, bool alive);
  // Refreshes the process CPU time and resident memory gauges.
  void updateProcessStats();

  const std::string& address() const { return address_; }
  // For a service's own metrics (same endpoint, same conventions).
  prometheus::Registry& registry() { return *registry_; }
  static prometheus::Histogram::BucketBoundaries latencyBuckets();

 private:
  std::string service_;
  std::string address_;
  std::unique_ptr<prometheus::Exposer> exposer_;
  std::shared_ptr<prometheus::Registry> registry_;
  prometheus::Counter& received_;
  prometheus::Counter& published_;
  prometheus::Family<prometheus::Counter>& removed_;
  prometheus::Family<prometheus::Counter>& rejected_;
  prometheus::Counter& restored_;
  prometheus::Histogram& processing_;
  prometheus::Histogram& latency_;
  prometheus::Histogram& hop_;
  prometheus::Family<prometheus::Gauge>& matched_;
  prometheus::Family<prometheus::Gauge>& upstream_alive_;
  prometheus::Gauge& cpu_seconds_;
  prometheus::Gauge& resident_bytes_;
};

}  // namespace scanfilter::dds_io
