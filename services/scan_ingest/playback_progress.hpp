#pragma once
#include <cstdint>
#include <string>

namespace scanfilter::ingest {

// Where a replay got to, kept in a small file so that a restarted ingest
// (after a crash, as systemd restarts it) continues after the last scan it
// handed to DDS instead of replaying the log from its start. A scan is
// recorded just before it is written: after a kill no scan is sent twice,
// and at most the one being written is lost besides the unacknowledged ones.
// The count, not a stamp: some logs' stamps step back. "" = no file, always
// from the start.
class PlaybackProgress {
 public:
  explicit PlaybackProgress(std::string path) : path_(std::move(path)) {}

  // Scans already published by an earlier run (0 without a file). Throws
  // InputError naming the file for a malformed one.
  std::uint64_t load() const;
  // `published` scans of the source are out: written to a temporary file and
  // renamed, so a kill leaves the old count or the new, never a torn one.
  void record(std::uint64_t published) const;
  bool enabled() const { return !path_.empty(); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace scanfilter::ingest
