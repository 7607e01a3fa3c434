#pragma once
#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>

#include "scanfilter/dds/checked_type_support.hpp"
#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/progress_heartbeat.hpp"

namespace scanfilter::dds_io {

// A DataReader of one generated type on one topic that hands every valid
// sample, in order, to a callback on its own worker thread.
//
// Why a thread and not on_data_available: Fast DDS calls listeners on the
// transport's receive thread. A callback that publishes on a reliable
// keep-all stream may block until the next stage acknowledges, and those
// acknowledgements arrive on that same thread: the pipeline deadlocks. Taking
// samples on a worker instead keeps the receive thread free, and a slow
// worker simply leaves samples unacknowledged, which slows the writer
// upstream: back-pressure without loss.
template <typename PubSubType>
class TypedReader : private eprosima::fastdds::dds::DataReaderListener {
 public:
  using Sample = typename PubSubType::type;
  using Callback = std::function<void(Sample&)>;
  // Called (on a Fast DDS thread) with the number of matched writers whenever
  // it changes: one matched, or discovery dropped one (it left, or its
  // participant's lease ran out: a crash, a frozen process, a lost link).
  using WritersCallback = std::function<void(int matched_writers)>;

  TypedReader(DdsParticipant& participant, const std::string& topic_name,
              const eprosima::fastdds::dds::DataReaderQos& qos, Callback callback,
              WritersCallback on_writers = {})
      : participant_(participant),
        callback_(std::move(callback)),
        on_writers_(std::move(on_writers)),
        heartbeat_("the reader of " + topic_name) {
    auto* topic = participant.topic(topic_name, eprosima::fastdds::dds::TypeSupport(new CheckedPubSubType<PubSubType>()));
    reader_ = participant.subscriber()->create_datareader(topic, qos, this,
                                                          eprosima::fastdds::dds::StatusMask::subscription_matched());
    if (reader_ == nullptr) throw std::runtime_error("cannot create a reader on " + topic_name);
    worker_ = std::thread([this] { takeLoop(); });
  }
  ~TypedReader() override {
    stop_ = true;
    worker_.join();  // finishes the sample in hand: nothing half-processed
    reader_->set_listener(nullptr);
    participant_.subscriber()->delete_datareader(reader_);
  }
  TypedReader(const TypedReader&) = delete;
  TypedReader& operator=(const TypedReader&) = delete;

  int matchedWriters() const { return matched_.load(); }

 private:
  static constexpr int32_t kPollNanoseconds = 50'000'000;  // stop_ is checked this often when idle

  void takeLoop() {
    eprosima::fastdds::dds::SampleInfo info;
    while (!stop_) {
      heartbeat_.beat();  // the systemd watchdog pings only while this is recent
      if (!reader_->wait_for_unread_message({0, kPollNanoseconds})) continue;
      while (!stop_ && reader_->take_next_sample(&sample_, &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
        if (info.valid_data) callback_(sample_);
        heartbeat_.beat();
      }
    }
  }
  void on_subscription_matched(eprosima::fastdds::dds::DataReader*,
                               const eprosima::fastdds::dds::SubscriptionMatchedStatus& status) override {
    matched_ = status.current_count;
    if (on_writers_) on_writers_(status.current_count);
  }

  DdsParticipant& participant_;
  Callback callback_;
  WritersCallback on_writers_;
  eprosima::fastdds::dds::DataReader* reader_ = nullptr;
  Sample sample_;  // reused: no allocation per scan once sizes settle
  std::atomic<int> matched_{0};
  std::atomic<bool> stop_{false};
  ProgressHeartbeat heartbeat_;
  std::thread worker_;
};

}  // namespace scanfilter::dds_io
