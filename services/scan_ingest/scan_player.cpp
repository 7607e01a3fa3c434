#include "scan_player.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include <spdlog/spdlog.h>

#include "scanfilter/dds/shutdown_signal.hpp"

namespace scanfilter::ingest {

bool parsePlaybackRate(const std::string& text, PlaybackRate& rate) {
  if (text == "recorded") {
    rate = {false, 1.0};
    return true;
  }
  if (text == "max") {
    rate = {true, 1.0};
    return true;
  }
  char* end = nullptr;
  const double factor = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !(factor > 0.0)) return false;
  rate = {false, factor};
  return true;
}

std::uint64_t ScanPlayer::play() {
  stopped_short_ = false;
  const SensorInfo& sensor = source_.header().sensor;
  ScanRecord record;
  dds_io::LabeledScanMsg msg;
  // Sequence numbers continue across a restart: the stages downstream see one stream.
  const std::uint64_t resume_after = progress_.load();
  std::uint64_t sequence = 0;
  for (; sequence < resume_after && source_.next(record); ++sequence) {}
  if (resume_after > 0)
    spdlog::info("resuming after the {} scans {} records as published", sequence, progress_.path());
  const std::uint64_t first_sequence = sequence;
  bool first = true;
  Stamp first_stamp, latest_stamp;  // the pause before a scan counts from the latest stamp played, not a regression
  const auto start = std::chrono::steady_clock::now();
  const double held_at_start = writer_.heldSeconds();
  while (!dds_io::ShutdownSignal::requested() && source_.next(record)) {
    if (first) first_stamp = latest_stamp = record.scan.stamp, first = false;
    if (!rate_.as_fast_as_accepted) {
      // Sleep until the scan's recorded time, scaled by the speed; the time
      // the writer held (no reader downstream) does not count.
      const double due_s =
          record.scan.stamp.secondsSince(first_stamp) / rate_.speed + (writer_.heldSeconds() - held_at_start);
      const auto due = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                   std::chrono::duration<double>(due_s));
      if (waitUntilDue(due, sequence, record.scan.stamp.secondsSince(latest_stamp) / rate_.speed))
        break;  // stopped while waiting
    }
    latest_stamp = std::max(latest_stamp, record.scan.stamp);
    record.scan.labels.clear();  // the filters write labels; a log's old ones are not passed on
    const dds_io::TimeMsg received = dds_io::wallClockNow();
    dds_io::toMessage(record.scan, sensor, sequence, msg);
    dds_io::stampStage(msg, "scan_ingest", received);
    // Counted as published before it is written: write() may deliver it and
    // then wait long for acknowledgements, and a kill there must not make the
    // restarted ingest send it again (a duplicate downstream); a kill between
    // the two loses it instead, like the rest of the unacknowledged window.
    progress_.record(sequence + 1);
    if (!writer_.write(msg)) {
      progress_.record(sequence);  // not out after all
      if (dds_io::ShutdownSignal::requested()) break;  // stopped while holding for a reader
      spdlog::error("scan {} not accepted by the pipeline within max_blocking_s (Fast DDS return code {}); stopping",
                    sequence, writer_.lastError());
      stopped_short_ = true;
      break;
    }
    metrics_.scanPublished();
    ++sequence;
  }
  return sequence - first_sequence;
}

bool ScanPlayer::waitUntilDue(std::chrono::steady_clock::time_point due, std::uint64_t sequence, double pause_s) const {
  using std::chrono::steady_clock;
  // Decided on the recording, not on the time left: the same log says the
  // same, however busy the machine.
  if (wait_notice_s_ > 0.0 && pause_s > wait_notice_s_)
    spdlog::info("waiting {:.1f} s for scan {}: the recording pauses {:.1f} s before it "
                 "(source.rate: max, or a larger speed factor, plays faster)",
                 std::max(0.0, std::chrono::duration<double>(due - steady_clock::now()).count()), sequence, pause_s);
  return dds_io::ShutdownSignal::waitUntil(due);  // SIGINT/SIGTERM end it at once, however long the pause
}

}  // namespace scanfilter::ingest
