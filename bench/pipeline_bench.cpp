// Pipeline benchmark: the jump_filter and penetration_filter processes
// between this program (as the ingest, and as the subscriber of
// rt/labeled_scan), against a bare Fast DDS hop of the same payload, rates
// and QoS measured in the same run (an echo process that only forwards).
//
//   bench/run-pipeline-bench.sh [--secure]   (a private network namespace around it)
//   build/bench/pipeline_bench BUILD_DIR PROFILES_XML [--throughput N] [--latency-scans N]
//                              [--keystore DIR --filter-config FILE]
//
// Reports throughput (scans/s through both filters, with a zero-loss check)
// and p50/p99 of each hop and end to end at 10 Hz and 40 Hz. With --keystore
// (deploy/security/make-keystore.sh, plus the bench's own enclaves: see
// run-pipeline-bench.sh) it measures everything twice in the same run, plain
// and with DDS Security (every participant authenticated, access-controlled,
// encrypted), and tabulates what security costs.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/dds/typed_reader.hpp"
#include "scanfilter/dds/typed_writer.hpp"
#include "scanfilter/sim/scan_simulator.hpp"
#include "scanfilter_typesPubSubTypes.h"

extern char** environ;

using namespace scanfilter;
using namespace scanfilter::dds_io;
using Writer = TypedWriter<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType>;
using Reader = TypedReader<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType>;

namespace {

constexpr int kDomain = 42;
constexpr const char* kPingTopic = "rt/bench_ping";
constexpr const char* kPongTopic = "rt/bench_pong";

pid_t spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
    std::perror(args[0].c_str());
    std::exit(1);
  }
  return pid;
}

// User + system CPU seconds of a process so far (/proc/PID/stat; "self" for this one).
double cpuSeconds(const std::string& pid) {
  std::FILE* f = std::fopen(("/proc/" + pid + "/stat").c_str(), "r");
  if (f == nullptr) return 0.0;
  char buffer[1024] = {};
  const std::size_t n = std::fread(buffer, 1, sizeof(buffer) - 1, f);
  std::fclose(f);
  // Fields 14 and 15 (utime, stime) follow the command name's closing parenthesis.
  const char* p = std::strrchr(buffer, ')');
  if (p == nullptr || n == 0) return 0.0;
  unsigned long utime = 0, stime = 0;
  if (std::sscanf(p + 2, "%*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %lu %lu", &utime, &stime) != 2) return 0.0;
  return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

// What arrives at the end of a chain: per scan, the timing trail and when it came.
struct Arrivals {
  std::mutex mutex;
  std::vector<LabeledScanMsg> scans;
  std::vector<double> arrived;
  std::atomic<std::size_t> count{0};
  void add(const LabeledScanMsg& msg) {
    const double now = toSeconds(wallClockNow());
    std::lock_guard lock(mutex);
    scans.push_back(msg);
    arrived.push_back(now);
    ++count;
  }
  void clear() {
    std::lock_guard lock(mutex);
    scans.clear();
    arrived.clear();
    count = 0;
  }
};

bool waitFor(const std::atomic<std::size_t>& count, std::size_t n, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (count < n && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  return count >= n;
}

// Publishes `scans` (cycled) at `rate_hz` (0: as fast as accepted).
void publish(Writer& writer, const std::vector<Scan>& scans, const SensorInfo& sensor, std::size_t n, double rate_hz,
             std::uint64_t first_sequence) {
  LabeledScanMsg msg;
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < n; ++k) {
    if (rate_hz > 0)
      std::this_thread::sleep_until(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                std::chrono::duration<double>(static_cast<double>(k) / rate_hz)));
    Scan scan = scans[k % scans.size()];
    scan.stamp = Stamp::fromSeconds(static_cast<double>(first_sequence + k) * 0.1);  // strictly increasing stamps for step 2
    toMessage(scan, sensor, first_sequence + k, msg);
    stampStage(msg, "bench_source", wallClockNow());
    if (!writer.write(msg)) std::fprintf(stderr, "write failed at %zu\n", k);
  }
}

// The bare yardstick: forwards every sample from ping to pong, stamping it.
int runEcho(const std::string& profiles, const std::string& enclave) {
  ParticipantSettings settings;
  settings.domain_id = kDomain;
  settings.profiles_file = profiles;
  settings.name = "bench_echo";
  settings.security.enclave = enclave;
  DdsParticipant participant(settings);
  StreamQos qos;
  Writer pong(participant, kPongTopic, losslessWriterQos(qos));
  pong.setFlowControl(flowControlWindow(qos), qos.max_blocking_s);
  Reader ping(participant, kPingTopic, losslessReaderQos(qos), [&](LabeledScanMsg& msg) {
    stampStage(msg, "echo", wallClockNow());
    pong.write(msg);
  });
  pause();  // until the benchmark kills it
  return 0;
}

struct HopStats {
  std::vector<double> hop1, hop2, hop3, end_to_end;
};

// Latencies from the timing trails: source sent -> jump received -> jump sent
// -> penetration received -> penetration sent -> arrived here.
HopStats pipelineLatencies(Arrivals& a) {
  HopStats s;
  for (std::size_t i = 0; i < a.scans.size(); ++i) {
    const auto& t = a.scans[i].timing();
    if (t.size() < 3) continue;
    s.hop1.push_back(toSeconds(t[1].received()) - toSeconds(t[0].sent()));
    s.hop2.push_back(toSeconds(t[2].received()) - toSeconds(t[1].sent()));
    s.hop3.push_back(a.arrived[i] - toSeconds(t[2].sent()));
    s.end_to_end.push_back(a.arrived[i] - toSeconds(t[0].sent()));
  }
  return s;
}

std::vector<double> bareHops(Arrivals& a) {
  std::vector<double> hops;
  for (const auto& scan : a.scans)
    if (scan.timing().size() >= 2) hops.push_back(toSeconds(scan.timing()[1].received()) - toSeconds(scan.timing()[0].sent()));
  return hops;
}

void row(const char* what, const std::vector<double>& v) {
  std::printf("| %s | %zu | %.0f | %.0f |\n", what, v.size(), 1e6 * percentile(v, 0.5), 1e6 * percentile(v, 0.99));
}

constexpr double kRates[] = {10.0, 40.0};
constexpr std::size_t kRateCount = std::size(kRates);

// One run's figures, for the plain / secured comparison.
struct RunResult {
  double scans_per_s = 0;
  bool zero_loss = false;
  std::vector<double> bare[kRateCount], end_to_end[kRateCount];
};

// How one run is set up: plain (no enclaves) or secured.
struct RunSetup {
  std::string label;
  std::string build, profiles;
  std::string jump_config, penetration_config;  // empty: the services' CLI defaults
  std::string source_enclave, echo_enclave;     // empty: security off
};

// A service config in `dir` for a secured run: the domain, the profile, a
// quiet log, the enclave, and the filter parameters.
std::string writeServiceConfig(const std::string& dir, const std::string& name, const std::string& metrics,
                               const std::string& profiles, const std::string& enclave, const std::string& filter) {
  const std::string path = dir + "/" + name + ".yaml";
  std::ofstream out(path);
  out << "service:\n  domain_id: " << kDomain << "\n  profiles_file: " << profiles << "\n  metrics_address: " << metrics
      << "\n  log_level: warn\n  security: {enclave: " << enclave << "}\nfilter: {config: " << filter << "}\n";
  if (!out) throw std::runtime_error("cannot write " + path);
  return path;
}

std::vector<std::string> serviceCommand(const RunSetup& setup, const std::string& name, const std::string& metrics,
                                        const std::string& config) {
  if (!config.empty()) return {setup.build + "/services/" + name, "--config", config};
  return {setup.build + "/services/" + name, "--domain", std::to_string(kDomain), "--metrics-address", metrics,
          "--log-level", "warn"};
}

RunResult measure(const RunSetup& setup, const char* self, std::size_t throughput_n, std::size_t latency_n) {
  std::printf("\n## %s\n\n", setup.label.c_str());
  std::vector<pid_t> children = {spawn(serviceCommand(setup, "jump_filter", "127.0.0.1:19572", setup.jump_config)),
                                 spawn(serviceCommand(setup, "penetration_filter", "127.0.0.1:19573", setup.penetration_config)),
                                 spawn({self, "--echo", setup.profiles, setup.echo_enclave})};

  // 360-beam frames of the hall (the scan log format's demo robot).
  sim::ScanSimulator simulator(sim::findScene("hall"), 1);
  const SensorInfo sensor = simulator.header().sensor;
  std::vector<Scan> frames;
  ScanRecord record;
  for (int k = 0; k < 100 && simulator.next(record); ++k) frames.push_back(record.scan);

  RunResult result;
  {
    ParticipantSettings settings;
    settings.domain_id = kDomain;
    settings.profiles_file = setup.profiles;
    settings.name = "bench_source";
    settings.security.enclave = setup.source_enclave;
    DdsParticipant participant(settings);
    StreamQos qos;
    Writer source(participant, rosTopic("", kPosedScanTopic), losslessWriterQos(qos));
    source.setFlowControl(flowControlWindow(qos), qos.max_blocking_s);
    Writer ping(participant, kPingTopic, losslessWriterQos(qos));
    ping.setFlowControl(flowControlWindow(qos), qos.max_blocking_s);
    Arrivals out, pong_out;
    Reader sink(participant, rosTopic("", kLabeledScanTopic), losslessReaderQos(qos), [&](LabeledScanMsg& m) { out.add(m); });
    Reader pong(participant, kPongTopic, losslessReaderQos(qos), [&](LabeledScanMsg& m) { pong_out.add(m); });
    // Authentication handshakes make a secured start slower: give matching time.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(40);
    const auto all_matched = [&] {
      return source.matchedReaders() >= 1 && sink.matchedWriters() >= 1 && ping.matchedReaders() >= 1 &&
             pong.matchedWriters() >= 1;
    };
    while (!all_matched() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (!all_matched()) {
      for (pid_t pid : children) kill(pid, SIGTERM);
      for (pid_t pid : children) waitpid(pid, nullptr, 0);
      throw std::runtime_error(setup.label + ": the filters and the echo did not match within 40 s (see their errors above)");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the filters' inner link matches too

    std::uint64_t sequence = 0;
    // Throughput: as fast as the pipeline accepts, with each process's CPU over it.
    const std::vector<std::pair<std::string, std::string>> processes = {
        {"jump_filter", std::to_string(children[0])}, {"penetration_filter", std::to_string(children[1])},
        {"this benchmark (source and subscriber)", "self"}};
    std::vector<double> cpu_before;
    for (const auto& p : processes) cpu_before.push_back(cpuSeconds(p.second));
    const auto t0 = std::chrono::steady_clock::now();
    publish(source, frames, sensor, throughput_n, 0.0, sequence);
    const bool all = waitFor(out.count, throughput_n, 60.0);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    bool in_order = true;
    for (std::size_t i = 0; i < out.scans.size(); ++i) in_order &= out.scans[i].sequence_number() == sequence + i;
    result.scans_per_s = static_cast<double>(out.count) / seconds;
    result.zero_loss = all && in_order;
    std::printf("throughput: %zu scans of %zu beams in %.2f s = %.0f scans/s; received %zu, %s, %s\n", throughput_n,
                frames[0].size(), seconds, result.scans_per_s, out.count.load(), all ? "zero loss" : "LOSS",
                in_order ? "in order" : "OUT OF ORDER");
    sequence += throughput_n;
    std::printf("\n| process | CPU s | cores | CPU µs per scan |\n|---|---|---|---|\n");
    double total_cpu = 0.0;
    for (std::size_t k = 0; k < processes.size(); ++k) {
      const double cpu = cpuSeconds(processes[k].second) - cpu_before[k];
      total_cpu += cpu;
      std::printf("| %s | %.2f | %.2f | %.0f |\n", processes[k].first.c_str(), cpu, cpu / seconds,
                  1e6 * cpu / static_cast<double>(throughput_n));
    }
    std::printf("| all | %.2f | %.2f | %.0f |\n", total_cpu, total_cpu / seconds,
                1e6 * total_cpu / static_cast<double>(throughput_n));

    for (std::size_t r = 0; r < kRateCount; ++r) {
      const double rate = kRates[r];
      out.clear();
      pong_out.clear();
      // The bare hop and the pipeline, one after the other at the same rate.
      publish(ping, frames, sensor, latency_n, rate, sequence);
      waitFor(pong_out.count, latency_n, 30.0);
      publish(source, frames, sensor, latency_n, rate, sequence + latency_n);
      waitFor(out.count, latency_n, 30.0);
      sequence += 2 * latency_n;
      const HopStats p = pipelineLatencies(out);
      const std::vector<double> bare = bareHops(pong_out);
      result.bare[r] = bare;
      result.end_to_end[r] = p.end_to_end;
      std::printf("\n%.0f Hz, %zu scans (µs)\n| latency | samples | p50 | p99 |\n|---|---|---|---|\n", rate, latency_n);
      row("bare Fast DDS hop (same payload and QoS)", bare);
      row("hop: source -> jump_filter", p.hop1);
      row("hop: jump_filter -> penetration_filter", p.hop2);
      row("hop: penetration_filter -> subscriber", p.hop3);
      row("end to end (incl. both filters)", p.end_to_end);
      const double bare50 = percentile(bare, 0.5), bare99 = percentile(bare, 0.99);
      std::printf("hop / bare: p50 %.2f %.2f %.2f, p99 %.2f %.2f %.2f\n", percentile(p.hop1, 0.5) / bare50,
                  percentile(p.hop2, 0.5) / bare50, percentile(p.hop3, 0.5) / bare50, percentile(p.hop1, 0.99) / bare99,
                  percentile(p.hop2, 0.99) / bare99, percentile(p.hop3, 0.99) / bare99);
    }
  }
  for (pid_t pid : children) kill(pid, SIGTERM);
  for (pid_t pid : children) waitpid(pid, nullptr, 0);
  return result;
}

void compareRow(const char* what, double plain, double secured) {
  std::printf("| %s | %.0f | %.0f | %.2f |\n", what, plain, secured, plain > 0 ? secured / plain : 0.0);
}

// What DDS Security costs: the two runs side by side.
void printComparison(const RunResult& plain, const RunResult& secured) {
  std::printf("\n## DDS Security cost (same run)\n\n| measure | plain | secured | secured / plain |\n|---|---|---|---|\n");
  compareRow("throughput (scans/s)", plain.scans_per_s, secured.scans_per_s);
  for (std::size_t r = 0; r < kRateCount; ++r) {
    char label[96];
    for (const auto& [name, q] : {std::pair{"p50", 0.5}, std::pair{"p99", 0.99}}) {
      std::snprintf(label, sizeof label, "%.0f Hz end to end %s (µs)", kRates[r], name);
      compareRow(label, 1e6 * percentile(plain.end_to_end[r], q), 1e6 * percentile(secured.end_to_end[r], q));
      std::snprintf(label, sizeof label, "%.0f Hz bare hop %s (µs)", kRates[r], name);
      compareRow(label, 1e6 * percentile(plain.bare[r], q), 1e6 * percentile(secured.bare[r], q));
    }
  }
  std::printf("zero loss: plain %s, secured %s\n", plain.zero_loss ? "yes" : "NO", secured.zero_loss ? "yes" : "NO");
}

}  // namespace

int main(int argc, char** argv) {
  // The echo child this program spawns of itself (below): not a user's command.
  if (argc >= 3 && std::string(argv[1]) == "--echo") return runEcho(argv[2], argc >= 4 ? argv[3] : "");
  std::string build, profiles, keystore, filter_config;
  std::size_t throughput_n = 2000, latency_n = 200;
  CLI::App app{"The DDS pipeline's throughput and latency against a bare Fast DDS hop (bench/run-pipeline-bench.sh)"};
  app.add_option("build_dir", build, "build directory holding services/jump_filter and services/penetration_filter")
      ->required()
      ->check(CLI::ExistingDirectory);
  app.add_option("profiles_xml", profiles, "Fast DDS profiles (deploy/fastdds-loopback.xml)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("--throughput", throughput_n, "scans sent as fast as the pipeline accepts")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_option("--latency-scans", latency_n, "scans sent at each rate for the latencies")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  auto* keystore_option =
      app.add_option("--keystore", keystore,
                     "also measure with DDS Security: a keystore for domain 42 with the enclaves /scanfilter/"
                     "{jump_filter,penetration_filter,bench_source,bench_echo} (run-pipeline-bench.sh --secure makes it)")
          ->check(CLI::ExistingDirectory);
  app.add_option("--filter-config", filter_config, "filter parameters for the secured run's services (config/filter.yaml)")
      ->check(CLI::ExistingFile)
      ->needs(keystore_option);
  keystore_option->needs(app.get_option("--filter-config"));
  CLI11_PARSE(app, argc, argv);

  try {
    const RunSetup plain{"plain (no DDS Security)", build, profiles, "", "", "", ""};
    const RunResult plain_result = measure(plain, argv[0], throughput_n, latency_n);
    if (keystore.empty()) return 0;
    const std::string enclaves = keystore + "/enclaves/scanfilter";
    const auto dir = std::filesystem::temp_directory_path() / ("pipeline_bench." + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    const RunSetup secured{
        "DDS Security (PKI-DH, access control, AES-GCM on discovery, RTPS messages and data)", build, profiles,
        writeServiceConfig(dir.string(), "jump_filter", "127.0.0.1:19572", profiles, enclaves + "/jump_filter", filter_config),
        writeServiceConfig(dir.string(), "penetration_filter", "127.0.0.1:19573", profiles, enclaves + "/penetration_filter",
                           filter_config),
        enclaves + "/bench_source", enclaves + "/bench_echo"};
    const RunResult secured_result = measure(secured, argv[0], throughput_n, latency_n);
    std::filesystem::remove_all(dir);
    printComparison(plain_result, secured_result);
    return plain_result.zero_loss && secured_result.zero_loss ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pipeline_bench: error: %s\n", e.what());
    return 1;
  }
}
