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

DataWriterQos losslessWriterQos(const StreamQos& q) {
  DataWriterQos qos = DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
  qos.reliability().max_blocking_time = toDuration(q.max_blocking_s);
  qos.history().kind = KEEP_ALL_HISTORY_QOS;
  // Twice the flow-control window (flowControlWindow): the history never fills.
  qos.resource_limits().max_samples = 2 * q.queue_depth;
  qos.resource_limits().max_instances = 1;
  qos.resource_limits().max_samples_per_instance = 2 * q.queue_depth;
  qos.durability().kind = VOLATILE_DURABILITY_QOS;
  // Acknowledgements come back after a heartbeat; Fast DDS's default period
  // of 3 s would make every flow-control wait last seconds.
  qos.reliable_writer_qos().times.heartbeatPeriod = toDuration(kHeartbeatPeriodS);
  qos.reliable_writer_qos().times.nackResponseDelay = toDuration(0.0);
  return qos;
}

DataReaderQos losslessReaderQos(const StreamQos& q) {
  DataReaderQos qos = DATAREADER_QOS_DEFAULT;
  qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
  qos.history().kind = KEEP_ALL_HISTORY_QOS;
  qos.resource_limits().max_samples = 2 * q.queue_depth;
  qos.resource_limits().max_instances = 1;
  qos.resource_limits().max_samples_per_instance = 2 * q.queue_depth;
  qos.reliable_reader_qos().times.heartbeatResponseDelay = toDuration(0.0);
  qos.durability().kind = VOLATILE_DURABILITY_QOS;
  return qos;
}

DataWriterQos rosDefaultWriterQos() {
  DataWriterQos qos = DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
  qos.history().kind = KEEP_LAST_HISTORY_QOS;
  qos.history().depth = kRosDefaultDepth;
  qos.durability().kind = VOLATILE_DURABILITY_QOS;
  return qos;
}

DataReaderQos rosDefaultReaderQos() {
  DataReaderQos qos = DATAREADER_QOS_DEFAULT;
  qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
  qos.history().kind = KEEP_LAST_HISTORY_QOS;
  qos.history().depth = kRosDefaultDepth;
  qos.durability().kind = VOLATILE_DURABILITY_QOS;
  return qos;
}

DataReaderQos sensorDataReaderQos(int depth) {
  DataReaderQos qos = DATAREADER_QOS_DEFAULT;
  qos.reliability().kind = BEST_EFFORT_RELIABILITY_QOS;
  qos.history().kind = KEEP_LAST_HISTORY_QOS;
  qos.history().depth = depth;
  qos.durability().kind = VOLATILE_DURABILITY_QOS;
  return qos;
}

DataWriterQos sensorDataWriterQos(int depth) {
  DataWriterQos qos = DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = BEST_EFFORT_RELIABILITY_QOS;
  qos.history().kind = KEEP_LAST_HISTORY_QOS;
  qos.history().depth = depth;
  qos.durability().kind = VOLATILE_DURABILITY_QOS;
  return qos;
}

}  // namespace scanfilter::dds_io
