// The installed binaries: found from where the binary itself is, so that
// `cmake --install BUILD --prefix P` works for any P chosen at install time.
// A binary in P/<bindir> reads P/<sysconfdir>/scanfilter, except that the
// prefix /usr keeps its configuration in /etc (GNUInstallDirs' rule, which
// cmake/Packaging.cmake follows when it installs the configs): the .deb's
// /usr/bin/scanfilter-jump-filter reads /etc/scanfilter/jump_filter.yaml.
#include "scanfilter/dds/default_paths.hpp"

#include <filesystem>

namespace scanfilter::dds_io {

namespace {

namespace fs = std::filesystem;

// P for a binary in P/<bindir> (SCANFILTER_INSTALL_BINDIR, e.g. "bin").
fs::path installPrefix() {
  fs::path dir = fs::read_symlink("/proc/self/exe").parent_path();
  const fs::path bindir = SCANFILTER_INSTALL_BINDIR;
  for (auto it = bindir.begin(); it != bindir.end(); ++it) dir = dir.parent_path();
  return dir;
}

fs::path sysconfDir() {
  const fs::path prefix = installPrefix();
  if (prefix == "/usr") return "/etc";
  return prefix / SCANFILTER_INSTALL_SYSCONFDIR;
}

}  // namespace

std::string defaultConfigDir() { return (sysconfDir() / "scanfilter").string(); }

std::string defaultProfilesFile() { return (sysconfDir() / "scanfilter" / "fastdds-loopback.xml").string(); }

}  // namespace scanfilter::dds_io
