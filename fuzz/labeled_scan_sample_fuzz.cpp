// LabeledScan samples as the filter stages and map_publisher receive them
// (rt/<ns>/posed_scan and on): raw CDR bytes, then everything the services do.
#include "sample_pipeline.hpp"
#include "scanfilter_typesPubSubTypes.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  scanfilter::fuzz::ServiceChain chain;
  scanfilter::dds_io::LabeledScanMsg msg;
  for (const auto frame : scanfilter::fuzz::splitFrames(data, size)) {
    if (!scanfilter::fuzz::deserialize<scanfilter_msgs::msg::dds_::LabeledScan_PubSubType>(frame, msg)) continue;
    chain.onPosedScan(msg);
  }
  return 0;
}
