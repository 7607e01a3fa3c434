#pragma once
#include <chrono>
#include <cstdint>
#include <string>

#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/service_metrics.hpp"
#include "playback_progress.hpp"
#include "scanfilter/dds/typed_writer.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter_typesPubSubTypes.h"

namespace scanfilter::ingest {

// How fast a recording is replayed.
struct PlaybackRate {
  bool as_fast_as_accepted = false;  // "max": the pipeline's reliable queues set the pace, nothing is lost
  double speed = 1.0;                // multiple of the recorded speed otherwise
};

// Publishes every scan of a source as a posed LabeledScan, paced by the
// recorded stamps (or by the pipeline), and stops early on SIGINT/SIGTERM.
// While the writer holds (a stage downstream is gone) the recorded clock
// stands still: the replay resumes where it was, nothing skipped. With a
// progress file it continues after the scans an earlier run published.
class ScanPlayer {
 public:
  using Writer = dds_io::TypedWriter<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType>;

  // A pause of more than `wait_notice_s` in the recording (at the rate's
  // speed) is logged before the wait, so that it is not taken for a hang; 0: never.
  ScanPlayer(ScanSource& source, Writer& writer, dds_io::ServiceMetrics& metrics, PlaybackRate rate,
             const PlaybackProgress& progress, double wait_notice_s)
      : source_(source),
        writer_(writer),
        metrics_(metrics),
        rate_(rate),
        progress_(progress),
        wait_notice_s_(wait_notice_s) {}

  // Plays the whole source (from where the progress file says); returns the
  // scans published by this run.
  std::uint64_t play();
  // Whether the last play() ended before the source's end because the
  // pipeline did not accept a scan (not because it was asked to stop).
  bool stoppedShort() const { return stopped_short_; }

 private:
  // Sleeps until `due`, the time scan `sequence` is to go out, or until a
  // shutdown is requested (then true); first says so when the recording
  // pauses there (`pause_s`, at the rate's speed) for more than wait_notice_s.
  bool waitUntilDue(std::chrono::steady_clock::time_point due, std::uint64_t sequence, double pause_s) const;

  ScanSource& source_;
  Writer& writer_;
  dds_io::ServiceMetrics& metrics_;
  PlaybackRate rate_;
  const PlaybackProgress& progress_;
  double wait_notice_s_;
  bool stopped_short_ = false;
};

// Parses a rate as written in the config: "recorded", "max" or a factor.
bool parsePlaybackRate(const std::string& text, PlaybackRate& rate);

}  // namespace scanfilter::ingest
