// Pipeline benchmark: the jump_filter and penetration_filter processes
// between this program (as the ingest, and as the subscriber of
// rt/labeled_scan), against a bare Fast DDS hop of the same payload, rates
// and QoS measured in the same run (an echo process that only forwards).
//
//   bench/run-pipeline-bench.sh        (a private network namespace around it)
//   build/bench/pipeline_bench BUILD_DIR PROFILES_XML [--throughput N] [--latency-scans N]
//
// Reports throughput (scans/s through both filters, with a zero-loss check)
// and p50/p99 of each hop and end to end at 10 Hz and 40 Hz.
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
int runEcho(const std::string& profiles) {
  ParticipantSettings settings{kDomain, profiles, "scanfilter_loopback", "bench_echo"};
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

}  // namespace

int main(int argc, char** argv) {
  // The echo child this program spawns of itself (below): not a user's command.
  if (argc >= 3 && std::string(argv[1]) == "--echo") return runEcho(argv[2]);
  std::string build, profiles;
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
  CLI11_PARSE(app, argc, argv);
  const std::string domain = std::to_string(kDomain);
  std::vector<pid_t> children = {
      spawn({build + "/services/jump_filter", "--domain", domain, "--metrics-address", "127.0.0.1:19572", "--log-level", "warn"}),
      spawn({build + "/services/penetration_filter", "--domain", domain, "--metrics-address", "127.0.0.1:19573", "--log-level", "warn"}),
      spawn({argv[0], "--echo", profiles})};

  // 360-beam frames of the hall (the scan log format's demo robot).
  sim::ScanSimulator simulator(sim::findScene("hall"), 1);
  const SensorInfo sensor = simulator.header().sensor;
  std::vector<Scan> frames;
  ScanRecord record;
  for (int k = 0; k < 100 && simulator.next(record); ++k) frames.push_back(record.scan);

  ParticipantSettings settings{kDomain, profiles, "scanfilter_loopback", "bench_source"};
  DdsParticipant participant(settings);
  StreamQos qos;
  Writer source(participant, rosTopic("", kPosedScanTopic), losslessWriterQos(qos));
  source.setFlowControl(flowControlWindow(qos), qos.max_blocking_s);
  Writer ping(participant, kPingTopic, losslessWriterQos(qos));
  ping.setFlowControl(flowControlWindow(qos), qos.max_blocking_s);
  Arrivals out, pong_out;
  Reader sink(participant, rosTopic("", kLabeledScanTopic), losslessReaderQos(qos), [&](LabeledScanMsg& m) { out.add(m); });
  Reader pong(participant, kPongTopic, losslessReaderQos(qos), [&](LabeledScanMsg& m) { pong_out.add(m); });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while ((source.matchedReaders() < 1 || sink.matchedWriters() < 1 || ping.matchedReaders() < 1 || pong.matchedWriters() < 1) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
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
  std::printf("throughput: %zu scans of %zu beams in %.2f s = %.0f scans/s; received %zu, %s, %s\n", throughput_n,
              frames[0].size(), seconds, static_cast<double>(out.count) / seconds, out.count.load(),
              all ? "zero loss" : "LOSS", in_order ? "in order" : "OUT OF ORDER");
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

  for (double rate : {10.0, 40.0}) {
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
  for (pid_t pid : children) kill(pid, SIGTERM);
  for (pid_t pid : children) waitpid(pid, nullptr, 0);
  return 0;
}
