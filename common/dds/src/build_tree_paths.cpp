// The build tree's binaries: the configs and profiles of the source tree
// they were built from (SCANFILTER_CONFIG_DIR, SCANFILTER_DEPLOY_DIR are set
// by CMake on this file only).
#include "scanfilter/dds/default_paths.hpp"

namespace scanfilter::dds_io {

std::string defaultConfigDir() { return SCANFILTER_CONFIG_DIR; }

std::string defaultProfilesFile() { return SCANFILTER_DEPLOY_DIR "/fastdds-loopback.xml"; }

}  // namespace scanfilter::dds_io
