#pragma once
// The accuracy programs' shared options and their checks
// (scanfilter/cli/option_checks.hpp says why CLI11's own are not used).
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scanfilter/cli/option_checks.hpp"

namespace scanfilter::bench {

// A simulator seed: digits only.
inline const CLI::Validator kSeedCheck = cli::wholeNumber("a seed");

// Scans per simulated log: 0 (the whole trajectory) or more.
inline const CLI::Range kFrameCountCheck(0, std::numeric_limits<int>::max(), "FRAMES");

// The options the programs that score held-out seeds share, said alike.
inline void addHeldOutSeedsOption(CLI::App& app, std::vector<std::uint64_t>& seeds) {
  app.add_option("--seeds", seeds, "simulator seeds scored (held out from the tuning seed)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(kSeedCheck);
}
inline void addMaxFramesOption(CLI::App& app, int& max_frames) {
  app.add_option("--max-frames", max_frames, "scans per simulated log (0: the whole trajectory)")
      ->capture_default_str()
      ->check(kFrameCountCheck);
}

}  // namespace scanfilter::bench
