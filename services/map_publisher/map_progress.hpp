#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace scanfilter::map_service {

// Which scans the saved map holds, saved beside it (BASE.progress) each time
// the map is: how many were integrated and the sequence number of the last.
// A publisher restarted from the saved map (load_on_start) continues the
// count, and whoever compares maps knows which scans the file has.
struct MapProgress {
  std::uint64_t scans_integrated = 0;
  std::optional<std::uint64_t> last_sequence;  // none before the first scan

  // BASE.progress, or an empty progress if there is none; throws InputError
  // naming the file for a malformed one.
  static MapProgress load(const std::string& base);
  // Written to a temporary file and renamed, like the map's files.
  void save(const std::string& base) const;
};

}  // namespace scanfilter::map_service
