// A subscriber that stops reading: reliable readers of rt/<ns>/scan_filtered
// (sensor_msgs/LaserScan), rt/<ns>/map (nav_msgs/OccupancyGrid, transient
// local, as a ROS map subscriber asks) and rt/<ns>/map_updates that take
// the first sample each and then never again, until SIGTERM. With
// --keep-all the readers keep every sample (the most a subscriber can ask
// the writers to hold for it); otherwise they keep the ROS default depth.
//
//   stalled_subscriber DOMAIN PROFILES_XML [NAMESPACE] [--keep-all]
//
// Prints "matched" once every reader matched a writer, and on exit how many
// samples each took (1 each: it stopped reading).
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/shutdown_signal.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter_typesPubSubTypes.h"

using namespace scanfilter::dds_io;
namespace fdds = eprosima::fastdds::dds;

namespace {

// A reader that takes one sample, then never reads again.
template <typename PubSubType>
class StalledReader {
 public:
  StalledReader(DdsParticipant& participant, const std::string& topic, fdds::DataReaderQos qos)
      : participant_(participant) {
    reader_ = participant.subscriber()->create_datareader(participant.topic(topic, fdds::TypeSupport(new PubSubType())), qos);
    if (reader_ == nullptr) {
      std::fprintf(stderr, "stalled_subscriber: cannot create a reader on %s\n", topic.c_str());
      std::exit(1);
    }
  }
  ~StalledReader() { participant_.subscriber()->delete_datareader(reader_); }

  bool matched() {
    fdds::SubscriptionMatchedStatus status;
    reader_->get_subscription_matched_status(status);
    return status.current_count > 0;
  }
  // Takes the first sample to arrive; afterwards does nothing.
  void takeFirst() {
    if (taken_ > 0) return;
    typename PubSubType::type sample;
    fdds::SampleInfo info;
    if (reader_->take_next_sample(&sample, &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) ++taken_;
  }
  int taken() const { return taken_; }

 private:
  DdsParticipant& participant_;
  fdds::DataReader* reader_ = nullptr;
  int taken_ = 0;
};

fdds::DataReaderQos stubbornQos(bool keep_all, bool transient_local) {
  fdds::DataReaderQos qos = rosDefaultReaderQos();
  if (keep_all) qos.history().kind = fdds::KEEP_ALL_HISTORY_QOS;
  if (transient_local) qos.durability().kind = fdds::TRANSIENT_LOCAL_DURABILITY_QOS;
  return qos;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || std::strcmp(argv[1], "--help") == 0) {
    std::printf("usage: stalled_subscriber DOMAIN PROFILES_XML [NAMESPACE] [--keep-all]\n");
    return argc < 3 ? 2 : 0;
  }
  std::string ns;
  bool keep_all = false;
  for (int k = 3; k < argc; ++k) {
    if (std::strcmp(argv[k], "--keep-all") == 0) keep_all = true;
    else ns = argv[k];
  }
  ShutdownSignal::install();
  ParticipantSettings settings;
  settings.domain_id = std::atoi(argv[1]);
  settings.profiles_file = argv[2];
  settings.name = "stalled_subscriber";
  DdsParticipant participant(settings);
  StalledReader<sensor_msgs::msg::dds_::LaserScan_PubSubType> scans(participant, rosTopic(ns, "scan_filtered"),
                                                                   stubbornQos(keep_all, false));
  StalledReader<nav_msgs::msg::dds_::OccupancyGrid_PubSubType> map(participant, rosTopic(ns, "map"),
                                                                  stubbornQos(keep_all, true));
  StalledReader<map_msgs::msg::dds_::OccupancyGridUpdate_PubSubType> updates(participant, rosTopic(ns, "map_updates"),
                                                                            stubbornQos(keep_all, false));
  bool announced = false;
  while (!ShutdownSignal::waitFor(std::chrono::milliseconds(20))) {
    if (!announced && scans.matched() && map.matched() && updates.matched()) {
      std::printf("matched\n");
      std::fflush(stdout);
      announced = true;
    }
    scans.takeFirst();
    map.takeFirst();
    updates.takeFirst();
  }
  std::printf("took %d scans, %d maps, %d map updates\n", scans.taken(), map.taken(), updates.taken());
  return 0;
}
