// Publishes malformed LabeledScans on rt/posed_scan, then one good scan: the
// jump_filter must count and drop each bad one and still filter the good one.
//   bad_sample_sender DOMAIN PROFILES_XML
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <thread>

#include "scanfilter/dds/dds_participant.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/dds/stream_qos.hpp"
#include "scanfilter/dds/topic_names.hpp"
#include "scanfilter/dds/typed_writer.hpp"
#include "room_scan_message.hpp"
#include "scanfilter_typesPubSubTypes.h"

using namespace scanfilter;
using namespace scanfilter::dds_io;

namespace {
constexpr int kBeams = test::kRoomScanBeams;
constexpr std::size_t kHugeBeams = 70000;  // above kMaxBeamsOnWire

// Scan `sequence`, stamped `sequence` seconds.
LabeledScanMsg goodScan(std::uint64_t sequence) {
  const Stamp stamp = Stamp::fromNanoseconds(static_cast<std::int64_t>(sequence) * Stamp::kNanosPerSecond);
  return test::roomScanMessage(sequence, stamp, "bad_sample_sender");
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  ParticipantSettings settings;
  settings.domain_id = std::atoi(argv[1]);
  settings.profiles_file = argv[2];
  settings.name = "bad_sample_sender";
  DdsParticipant participant(settings);
  TypedWriter<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType> writer(participant, rosTopic("", kPosedScanTopic),
                                                                         losslessWriterQos(StreamQos{}));
  for (int i = 0; i < 500 && writer.matchedReaders() < 1; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  if (writer.matchedReaders() < 1) return 1;
  std::this_thread::sleep_for(kDiscoverySettle);  // the reader must match us too, or a volatile sample is lost

  LabeledScanMsg msg = goodScan(0);
  msg.intensities().assign(kBeams - 1, 1.0f);  // length_mismatch
  writer.write(msg);
  msg = goodScan(1);
  msg.pose_x(std::numeric_limits<double>::quiet_NaN());  // nan_pose
  writer.write(msg);
  msg = goodScan(2);
  msg.angle_increment(0.0);  // zero_increment
  writer.write(msg);
  msg = goodScan(3);
  msg.ranges().assign(kHugeBeams, 1.0);  // too_many_beams
  writer.write(msg);
  msg = goodScan(4);
  msg.ranges().clear();  // empty
  writer.write(msg);
  msg = goodScan(5);  // and a good one
  writer.write(msg);
  writer.waitForAcknowledgments(10.0);
  std::puts("sent 5 bad scans and 1 good one");
  return 0;
}
