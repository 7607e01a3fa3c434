#include "scanfilter/dds/stream_qos.hpp"

#include <cmath>

namespace scanfilter::dds_io {

using namespace eprosima::fastdds::dds;

namespace {
constexpr int kRosDefaultDepth = 10;
constexpr double kHeartbeatPeriodS = 0.01;
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
  // Liveliness stays DDS's default (AUTOMATIC, no lease). With a lease, Fast
  // DDS 2.9 restarts a liveliness timer on every sample written and every
  // sample received: at 3,600 beams and 40 Hz that cost each service 2-6 %
  // of its CPU, 30-80 µs a scan (docs/performance.md). A stage learns that
  // its upstream is gone from discovery instead (UpstreamPresence: the
  // participant's lease).
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
