// A late-joining subscriber of rt/map: reliable + transient local, so it must
// get the current map at once although it was published before it started.
//   map_probe DOMAIN PROFILES_XML   prints "width height resolution occupied"
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/typed_reader.hpp"
#include "scanfilter_typesPubSubTypes.h"

using namespace scanfilter::dds_io;

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  ParticipantSettings settings;
  settings.domain_id = std::atoi(argv[1]);
  settings.profiles_file = argv[2];
  settings.name = "map_probe";
  DdsParticipant participant(settings);
  auto qos = rosDefaultReaderQos();
  qos.durability().kind = eprosima::fastdds::dds::TRANSIENT_LOCAL_DURABILITY_QOS;
  qos.history().depth = 1;
  std::atomic<bool> got{false};
  TypedReader<nav_msgs::msg::dds_::OccupancyGrid_PubSubType> reader(
      participant, "rt/map", qos, [&](nav_msgs::msg::dds_::OccupancyGrid_& map) {
        if (got.exchange(true)) return;
        int occupied = 0;
        for (char v : map.data()) occupied += v >= 65;
        std::printf("%u %u %.3f %d\n", map.info().width(), map.info().height(), map.info().resolution(), occupied);
        std::fflush(stdout);
      });
  for (int i = 0; i < 500 && !got; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return got ? 0 : 1;
}
