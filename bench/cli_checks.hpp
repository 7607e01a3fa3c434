#pragma once
// Checks of the accuracy programs' command-line values where CLI11's own say
// too little: CLI11 2.1 reads "-1" as the seed 2^64 - 1 without a word, and
// its NonNegativeNumber names DBL_MAX as the upper limit.
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace scanfilter::bench {

// A simulator seed: digits only.
inline const CLI::Validator kSeedCheck(
    [](std::string& value) -> std::string {
      const bool digits = !value.empty() && value.find_first_not_of("0123456789") == std::string::npos;
      return digits ? std::string() : "a seed is a non-negative integer, not " + value;
    },
    "SEED");

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
