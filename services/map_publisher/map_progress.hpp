#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace scanfilter::map_service {

// Which scans the saved map holds: how many were integrated and the sequence
// number of the last. Saved inside BASE.logodds (the note after the cells:
// one rename replaces the state and what it holds together, so a kill -9 at
// any moment cannot leave them one save apart) and, for people and scripts,
// as a copy in BASE.progress. A publisher restarted from the saved map
// (load_on_start) continues the count, and whoever compares maps knows which
// scans the file has.
struct MapProgress {
  std::uint64_t scans_integrated = 0;
  std::optional<std::uint64_t> last_sequence;  // none before the first scan

  // "scans_integrated: N\nlast_sequence: M\n" (the second line once there is one).
  std::string toText() const;
  // The inverse; throws InputError naming `origin` for malformed text.
  static MapProgress parse(const std::string& text, const std::string& origin);
  // BASE.progress, or an empty progress if there is none (maps saved before
  // the note existed); throws InputError naming the file for a malformed one.
  static MapProgress load(const std::string& base);
  // BASE.progress, written to a temporary file and renamed.
  void save(const std::string& base) const;
};

}  // namespace scanfilter::map_service
