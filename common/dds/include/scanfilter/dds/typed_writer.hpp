#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

#include <spdlog/spdlog.h>

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/DataWriterListener.hpp>

#include "scanfilter/dds/checked_type_support.hpp"
#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/progress_heartbeat.hpp"
#include "scanfilter/dds/stream_qos.hpp"

namespace scanfilter::dds_io {

// Discovery is asymmetric: a writer can see a reader matched before the
// reader has matched the writer, and a sample sent in between is lost even on
// a reliable stream (the reader starts from the writer's next sample). A
// source waits this long after its readers matched before its first sample.
inline constexpr auto kDiscoverySettle = std::chrono::milliseconds(300);

// A DataWriter of one generated type on one topic, counting its matched readers.
template <typename PubSubType>
class TypedWriter : private eprosima::fastdds::dds::DataWriterListener {
 public:
  using Sample = typename PubSubType::type;

  TypedWriter(DdsParticipant& participant, const std::string& topic_name,
              const eprosima::fastdds::dds::DataWriterQos& qos)
      : participant_(participant), topic_(topic_name) {
    auto* topic = participant.topic(topic_name, eprosima::fastdds::dds::TypeSupport(new CheckedPubSubType<PubSubType>()));
    writer_ = participant.publisher()->create_datawriter(topic, qos, this);
    if (writer_ == nullptr) throw std::runtime_error("cannot create a writer on " + topic_name);
  }
  ~TypedWriter() override { participant_.publisher()->delete_datawriter(writer_); }
  TypedWriter(const TypedWriter&) = delete;
  TypedWriter& operator=(const TypedWriter&) = delete;

  // Lossless streams: at most `window` samples may be unacknowledged; the
  // write that reaches it waits (up to `max_wait_s`) for every reader to
  // acknowledge. Fast DDS does not always block a full keep-all history (it
  // can fail at once), so the window keeps the history from ever filling.
  void setFlowControl(int window, double max_wait_s) {
    window_ = window;
    max_wait_s_ = max_wait_s;
  }

  // Lossless streams whose readers must be there (a volatile sample written
  // while they are not is lost for them): send() holds, logging once when it
  // starts and once when it resumes, while fewer than `required_readers` are
  // matched, and a flow-control wait that times out keeps holding instead of
  // giving up, until the readers acknowledge or discovery drops the silent
  // one (a crashed process: its participant's lease) and a new one matches.
  // Memory stays bounded by the keep-all history and the window. `stop`
  // (e.g. a shutdown request) ends a hold.
  void holdForReaders(int required_readers, std::function<bool()> stop) {
    required_readers_ = required_readers;
    stop_ = std::move(stop);
  }

  enum class Outcome {
    kSent,
    // Sent, but (with flow control) some reader did not acknowledge the
    // window within max_wait_s: a stalled or departed reader.
    kSentUnacknowledged,
    kRefused,  // Fast DDS did not take the sample
  };

  Outcome send(Sample& sample) {
    if (stop_ && !waitForRequiredReaders()) return Outcome::kRefused;
    const auto rc = writer_->write(&sample, eprosima::fastrtps::rtps::InstanceHandle_t());
    last_error_ = rc();
    if (rc != eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) return Outcome::kRefused;
    if (window_ > 0 && ++unacknowledged_ >= window_) {
      unacknowledged_ = 0;
      if (!waitForAcknowledgmentsBeating(max_wait_s_) && !(stop_ && holdUntilAcknowledged())) {
        last_error_ = eprosima::fastrtps::types::ReturnCode_t::RETCODE_TIMEOUT;
        return Outcome::kSentUnacknowledged;
      }
    }
    return Outcome::kSent;
  }

  // False when Fast DDS refused the sample, or (with flow control) when the
  // readers did not acknowledge the window in time: the stream is stalled.
  bool write(Sample& sample) { return send(sample) == Outcome::kSent; }

  // Waits until every matched reader acknowledged every sample written.
  bool waitForAcknowledgments(double seconds) {
    return writer_->wait_for_acknowledgments(toDuration(seconds)) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK;
  }

  // The Fast DDS return code of the last failed write (for the log).
  int lastError() const { return last_error_; }
  int matchedReaders() const { return matched_.load(); }
  // Seconds send() has spent holding so far (a paced source shifts its clock by them).
  double heldSeconds() const { return held_s_.load(); }

 private:
  static constexpr auto kHoldPoll = std::chrono::milliseconds(20);

  // Until `required_readers_` are matched and discovery settled; false if stopped first.
  bool waitForRequiredReaders() {
    if (matched_.load() >= required_readers_) return true;
    const auto start = std::chrono::steady_clock::now();
    spdlog::warn("holding {}: {} of {} required reader(s) matched; waiting for them", topic_, matched_.load(),
                 required_readers_);
    while (matched_.load() < required_readers_) {
      if (stop_()) return false;
      ProgressHeartbeat::beatThisThread();  // holding is this thread's work now, not a hang
      std::this_thread::sleep_for(kHoldPoll);
    }
    std::this_thread::sleep_for(kDiscoverySettle);  // the reader must match us too before a volatile sample
    resumed(start);
    return !stop_();
  }

  // The flow-control wait (up to max_blocking_s, 5 s by default: half the
  // watchdog's 10 s) in slices, beating the thread's heartbeat between them:
  // a reader slow to acknowledge is a wait, not this thread hanging.
  bool waitForAcknowledgmentsBeating(double seconds) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    const double slice = std::chrono::duration<double>(kHoldPoll).count();
    for (;;) {
      const double left = std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count();
      if (waitForAcknowledgments(std::clamp(left, 0.0, slice))) return true;
      if (left <= slice) return false;
      ProgressHeartbeat::beatThisThread();
    }
  }

  // After a flow-control wait timed out: until every matched reader
  // acknowledged (a dead one stops counting once discovery drops it); false if stopped first.
  bool holdUntilAcknowledged() {
    const auto start = std::chrono::steady_clock::now();
    spdlog::warn("holding {}: a reader has not acknowledged for {} s (crashed or stalled?); waiting for it, or for "
                 "discovery to drop it and a replacement to match", topic_, max_wait_s_);
    while (!waitForAcknowledgments(std::chrono::duration<double>(kHoldPoll).count())) {
      if (stop_()) return false;
      ProgressHeartbeat::beatThisThread();
    }
    resumed(start);
    return true;
  }

  void resumed(std::chrono::steady_clock::time_point since) {
    const double held = std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
    held_s_ = held_s_.load() + held;
    spdlog::info("resumed {} after holding {:.1f} s ({} reader(s) matched)", topic_, held, matched_.load());
  }

  void on_publication_matched(eprosima::fastdds::dds::DataWriter*,
                              const eprosima::fastdds::dds::PublicationMatchedStatus& status) override {
    matched_ = status.current_count;
  }

  DdsParticipant& participant_;
  std::string topic_;
  eprosima::fastdds::dds::DataWriter* writer_ = nullptr;
  int required_readers_ = 0;
  std::function<bool()> stop_;  // set: send() holds (holdForReaders)
  std::atomic<double> held_s_{0.0};
  std::atomic<int> matched_{0};
  int last_error_ = 0;
  int window_ = 0;  // 0: no flow control
  double max_wait_s_ = 0.0;
  int unacknowledged_ = 0;
};

}  // namespace scanfilter::dds_io
