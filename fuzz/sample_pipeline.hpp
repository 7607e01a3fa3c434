#pragma once
// What the services do with a sample from the wire, without the wire: raw
// CDR bytes deserialised by the generated type support (as Fast DDS does on
// receipt), validated, converted and filtered exactly as scan_ingest's live
// source, the two filter stages (FilterStage::onSample) and map_publisher
// do it, and the outgoing messages serialised as a writer would.
//
// A fuzz input holds up to kMaxFrames samples, each as a 2-byte little-endian
// length and that many bytes, so one input can drive a filter across scans.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <fastdds/rtps/common/SerializedPayload.h>

#include "scanfilter/dds/checked_type_support.hpp"
#include "scanfilter/dds/per_sensor_filter.hpp"
#include "scanfilter/dds/scan_message.hpp"
#include "scanfilter/jump_filter.hpp"
#include "scanfilter/occupancy_grid.hpp"
#include "scanfilter/penetration_filter.hpp"

namespace scanfilter::fuzz {

inline constexpr std::size_t kMaxFrames = 8;  // scans a filter sees per input: enough for its cache to work

// The samples in a fuzz input (see above); a trailing partial frame is its
// remaining bytes.
std::vector<std::span<const std::uint8_t>> splitFrames(const std::uint8_t* data, std::size_t size);

// Deserialises one sample as the services' readers do on receipt (through
// CheckedPubSubType, as TypedReader registers the type); false when the
// bytes are not a sample of that type (Fast DDS drops those).
template <typename PubSubType>
bool deserialize(std::span<const std::uint8_t> bytes, typename PubSubType::type& sample) {
  eprosima::fastrtps::rtps::SerializedPayload_t payload(static_cast<std::uint32_t>(bytes.size()));
  std::copy(bytes.begin(), bytes.end(), payload.data);
  payload.length = static_cast<std::uint32_t>(bytes.size());
  dds_io::CheckedPubSubType<PubSubType> type;
  return type.deserialize(&payload, &sample);
}

// Serialises a sample as a DataWriter does before sending it.
template <typename PubSubType>
void serialize(typename PubSubType::type& sample) {
  PubSubType type;
  eprosima::fastrtps::rtps::SerializedPayload_t payload(type.getSerializedSizeProvider(&sample)());
  if (!type.serialize(&sample, &payload)) throw std::runtime_error("a valid sample did not serialise");
}

// jump_filter, penetration_filter and map_publisher on one stream of scans.
class ServiceChain {
 public:
  ServiceChain();

  // A posed scan as scan_ingest publishes it: through both filter stages,
  // the penetration filter's LaserScan, and into the map.
  void onPosedScan(dds_io::LabeledScanMsg& msg);

 private:
  // FilterStage::onSample: validate, convert, label, publish; false when dropped.
  template <typename Filter>
  bool filterStage(dds_io::LabeledScanMsg& msg, const char* stage, dds_io::PerSensorFilter<Filter>& filters,
                   bool enabled);

  dds_io::PerSensorFilter<JumpFilter> jump_;
  dds_io::PerSensorFilter<PenetrationFilter> penetration_;
  FilterConfig config_;
  OccupancyGrid grid_;
  Scan scan_;
  SensorInfo sensor_;
  dds_io::LaserScanMsg laser_;
};

}  // namespace scanfilter::fuzz
