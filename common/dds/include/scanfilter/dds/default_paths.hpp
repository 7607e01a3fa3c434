#pragma once
#include <string>

namespace scanfilter::dds_io {

// Where a program looks by default for the services' configs and the Fast DDS
// profiles. Two implementations, one linked into each binary (see
// common/dds/CMakeLists.txt): the build tree's binaries read the source tree
// (src/build_tree_paths.cpp), the installed ones the directories beside their
// install prefix (src/installed_paths.cpp), so an installed service reads
// nothing from the source tree and the build tree's binaries are unaffected
// by an installation.

// The directory holding <service>.yaml.
std::string defaultConfigDir();
// The loopback-only Fast DDS profiles (fastdds-loopback.xml).
std::string defaultProfilesFile();

}  // namespace scanfilter::dds_io
