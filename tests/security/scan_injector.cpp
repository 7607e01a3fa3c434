// A participant that tries to get scans into the pipeline: creates a writer
// of LabeledScan on TOPIC and writes a valid scan every kPeriod for SECONDS,
// whether or not any reader matched (an intruder does not wait to be asked).
//
//   scan_injector DOMAIN PROFILES_XML TOPIC SECONDS [ENCLAVE]
//
// Prints "matched N, written M" and exits 0 when it could write; exits 3
// (printing "refused: ...") when its own participant refuses the topic or
// the writer (DDS Security access control), 4 when the participant cannot
// be created (e.g. its certificate is rejected at start), 2 on bad usage.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/typed_writer.hpp"
#include "room_scan_message.hpp"
#include "scanfilter_typesPubSubTypes.h"

using namespace scanfilter;
using namespace scanfilter::dds_io;

namespace {
constexpr auto kPeriod = std::chrono::milliseconds(20);  // 50 Hz: faster than any LiDAR the pipeline serves

// Scan `sequence`, stamped `sequence` + 1 seconds.
LabeledScanMsg validScan(std::uint64_t sequence) {
  const Stamp stamp = Stamp::fromNanoseconds(static_cast<std::int64_t>(sequence + 1) * Stamp::kNanosPerSecond);
  return test::roomScanMessage(sequence, stamp, "scan_injector");
}

void usage(std::FILE* out) {
  std::fputs("usage: scan_injector DOMAIN PROFILES_XML TOPIC SECONDS [ENCLAVE]\n"
             "  writes a valid LabeledScan on TOPIC every 20 ms for SECONDS, matched or not;\n"
             "  ENCLAVE: a DDS Security enclave directory (default: security off).\n"
             "  exit 0 wrote, 3 the topic or writer was refused, 4 no participant, 2 bad usage\n",
             out);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    usage(stdout);
    return 0;
  }
  if (argc != 5 && argc != 6) {
    usage(stderr);
    return 2;
  }
  ParticipantSettings settings;
  settings.domain_id = std::atoi(argv[1]);
  settings.profiles_file = argv[2];
  settings.name = "scan_injector";
  if (argc == 6) settings.security.enclave = argv[5];
  const std::string topic = argv[3];
  const double seconds = std::atof(argv[4]);

  std::unique_ptr<DdsParticipant> participant;
  try {
    participant = std::make_unique<DdsParticipant>(settings);
  } catch (const std::exception& e) {
    std::printf("no participant: %s\n", e.what());
    return 4;
  }
  try {
    TypedWriter<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType> writer(*participant, topic, losslessWriterQos(StreamQos{}));
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    std::uint64_t written = 0;
    int matched = 0;
    while (std::chrono::steady_clock::now() < end) {
      LabeledScanMsg msg = validScan(written);
      if (writer.write(msg)) ++written;
      matched = std::max(matched, writer.matchedReaders());
      std::this_thread::sleep_for(kPeriod);
    }
    std::printf("matched %d, written %llu\n", matched, static_cast<unsigned long long>(written));
    return 0;
  } catch (const std::exception& e) {
    std::printf("refused: %s\n", e.what());
    return 3;
  }
}
