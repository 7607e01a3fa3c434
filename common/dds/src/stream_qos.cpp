#include "scanfilter/dds/stream_qos.hpp"

#include <cmath>

namespace scanfilter::dds_io {

using namespace eprosima::fastdds::dds;

namespace {
constexpr int kRosDefaultDepth = 10;
constexpr double kHeartbeatPeriodS = 0.01;
// The stage topics' writers assert liveliness automatically and promise to do
// so within this lease; a reader sees its upstream gone (a crash, a frozen
// process) after at most this long, instead of the participant's lease.
constexpr double kStageLivelinessLeaseS = 1.0;
// Fast DDS asserts AUTOMATIC liveliness every announcement period (its
// default is never): four assertions per lease survive a lost packet or two.
constexpr double kStageLivelinessAnnouncementS = kStageLivelinessLeaseS / 4;
}  // namespace

eprosima::fastrtps::Duration_t toDuration(double seconds) {
  const auto whole = static_cast<int32_t>(std::floor(seconds));
  return {whole, static_cast<uint32_t>((seconds - whole) * 1e9)};
}

namespace {

// Reliable keep-all with room for twice the flow-control window
// (flowControlWindow), so the history never fills; volatile.
template <class Qos>
Qos keepAll(Qos qos, const StreamQos& q) {
  qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
  qos.history().kind = KEEP_ALL_HISTORY_QOS;
  qos.resource_limits().max_samples = 2 * q.queue_depth;
  qos.resource_limits().max_instances = 1;
  qos.resource_limits().max_samples_per_instance = 2 * q.queue_depth;
  qos.durability().kind = VOLATILE_DURABILITY_QOS;
  // AUTOMATIC with the same lease on both ends: compatible (offered lease <=
  // requested), and any reader that requests a longer lease or none (ROS 2's
  // default, Cyclone's) still matches the writers.
  qos.liveliness().kind = AUTOMATIC_LIVELINESS_QOS;
  qos.liveliness().lease_duration = toDuration(kStageLivelinessLeaseS);
  qos.liveliness().announcement_period = toDuration(kStageLivelinessAnnouncementS);
  return qos;
}

// Keep last `depth`, volatile, with the given reliability.
template <class Qos>
Qos keepLast(Qos qos, ReliabilityQosPolicyKind reliability, int depth) {
  qos.reliability().kind = reliability;
  qos.history().kind = KEEP_LAST_HISTORY_QOS;
  qos.history().depth = depth;
  qos.durability().kind = VOLATILE_DURABILITY_QOS;
  return qos;
}

}  // namespace

DataWriterQos losslessWriterQos(const StreamQos& q) {
  DataWriterQos qos = keepAll(DATAWRITER_QOS_DEFAULT, q);
  qos.reliability().max_blocking_time = toDuration(q.max_blocking_s);
  // Acknowledgements come back after a heartbeat; Fast DDS's default period
  // of 3 s would make every flow-control wait last seconds.
  qos.reliable_writer_qos().times.heartbeatPeriod = toDuration(kHeartbeatPeriodS);
  qos.reliable_writer_qos().times.nackResponseDelay = toDuration(0.0);
  return qos;
}

DataReaderQos losslessReaderQos(const StreamQos& q) {
  DataReaderQos qos = keepAll(DATAREADER_QOS_DEFAULT, q);
  qos.reliable_reader_qos().times.heartbeatResponseDelay = toDuration(0.0);
  return qos;
}

DataWriterQos rosDefaultWriterQos() {
  return keepLast(DATAWRITER_QOS_DEFAULT, RELIABLE_RELIABILITY_QOS, kRosDefaultDepth);
}

DataReaderQos rosDefaultReaderQos() {
  return keepLast(DATAREADER_QOS_DEFAULT, RELIABLE_RELIABILITY_QOS, kRosDefaultDepth);
}

DataReaderQos sensorDataReaderQos(int depth) {
  return keepLast(DATAREADER_QOS_DEFAULT, BEST_EFFORT_RELIABILITY_QOS, depth);
}

DataWriterQos sensorDataWriterQos(int depth) {
  return keepLast(DATAWRITER_QOS_DEFAULT, BEST_EFFORT_RELIABILITY_QOS, depth);
}

}  // namespace scanfilter::dds_io
