#pragma once
#include <fastcdr/exceptions/Exception.h>
#include <fastdds/rtps/common/SerializedPayload.h>

namespace scanfilter::dds_io {

// A generated type support whose deserialize() never throws. fastddsgen's
// code catches only NotEnoughMemoryException; a sample whose encapsulation
// header is malformed (the first byte not 0, found by fuzz/*_sample_fuzz)
// makes Fast CDR throw BadParamException, which would escape take_next_sample
// and end the service (std::terminate on the reader's thread). Such a sample
// is simply not a sample of this type: false, and Fast DDS drops it.
template <typename PubSubType>
class CheckedPubSubType : public PubSubType {
 public:
  bool deserialize(eprosima::fastrtps::rtps::SerializedPayload_t* payload, void* data) override {
    try {
      return PubSubType::deserialize(payload, data);
    } catch (const eprosima::fastcdr::exception::Exception&) {
      return false;
    }
  }
};

}  // namespace scanfilter::dds_io
