#pragma once
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>

namespace scanfilter::dds_io {

// Seconds as a Fast DDS duration.
eprosima::fastrtps::Duration_t toDuration(double seconds);

// QoS of the scan streams between the pipeline's stages: reliable and
// keep-all with a bounded queue, so a fast producer is slowed down by the
// slowest consumer (write() blocks) instead of losing scans.
// A deeper queue than this is a typo, not a need (the services use 64).
inline constexpr int kMaxQueueDepth = 100000;

struct StreamQos {
  int queue_depth = 64;           // samples buffered per writer and reader
  double max_blocking_s = 5.0;    // how long write() waits for room before failing
  // A filter stage holds its output (and so, by back-pressure, its input)
  // while fewer readers than this are matched on it: samples written to no
  // reader are lost on a volatile stream. 0: publish whatever is matched.
  int required_readers = 0;
};

eprosima::fastdds::dds::DataWriterQos losslessWriterQos(const StreamQos& q);
// Samples a lossless writer may have unacknowledged (TypedWriter::setFlowControl).
inline int flowControlWindow(const StreamQos& q) { return q.queue_depth; }
eprosima::fastdds::dds::DataReaderQos losslessReaderQos(const StreamQos& q);
// ROS 2's default (reliable, keep last 10, volatile): what rviz2 and nav2 expect.
eprosima::fastdds::dds::DataWriterQos rosDefaultWriterQos();
eprosima::fastdds::dds::DataReaderQos rosDefaultReaderQos();
// For a robot driver's rt/scan and rt/odom: best effort (ROS 2's sensor-data
// QoS), which matches both best-effort and reliable writers.
eprosima::fastdds::dds::DataReaderQos sensorDataReaderQos(int depth);
eprosima::fastdds::dds::DataWriterQos sensorDataWriterQos(int depth);

}  // namespace scanfilter::dds_io
