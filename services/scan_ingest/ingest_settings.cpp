#include "ingest_settings.hpp"

#include <filesystem>

#include "scanfilter/input_error.hpp"
#include "scanfilter/plausible_bounds.hpp"
#include "scanfilter/scan_source.hpp"
#include "scanfilter/sim/scene.hpp"
#include "scanfilter/yaml_section.hpp"

namespace scanfilter::ingest {

IngestSettings readIngestSettings(const dds_io::ServiceConfigFile& config) {
  IngestSettings s;
  YamlSection source(config.root, "source", config.path);
  source.readChoice("kind", s.kind, {"log", "simulator", "live"});
  source.read("path", s.path);
  source.read("scene", s.scene);
  source.read("seed", s.seed);
  source.read("carmen_range_max", s.carmen_range_max);
  std::string rate = "recorded";
  source.read("rate", rate);
  if (!parsePlaybackRate(rate, s.rate))
    source.fail("rate", "expected recorded, max or a speed factor > 0, got \"" + rate + "\"");
  if (s.kind == "log" && s.path.empty()) source.fail("path", "a log source needs a path");
  s.path = config.resolvePath(s.path);
  if (s.kind == "log") source.requireFile("path", s.path);
  if (s.kind == "simulator") {
    // A scene file, like the log, is found from the config's folder (a
    // service's working directory is /); a built-in name stays as it is.
    const std::string as_file = config.resolvePath(s.scene);
    std::error_code error;
    if (std::filesystem::is_regular_file(as_file, error)) s.scene = as_file;
    try {
      sim::findScene(s.scene);
    } catch (const InputError& e) {
      source.fail("scene", e.what());
    }
  }
  source.requireRange("carmen_range_max", s.carmen_range_max, kMinCarmenRangeMax, kMaxPlausibleRange,
                      "0.01-10000 (m; CARMEN logs write 80 for no return)");
  source.rejectUnknownKeys();
  YamlSection live(config.root, "live", config.path);
  live.read("scan_topic", s.live.scan_topic);
  live.read("odom_topic", s.live.odom_topic);
  std::vector<double> mount = {0.0, 0.0, 0.0};
  live.read("mount", mount);
  if (mount.size() != 3) live.fail("mount", "expected [x, y, yaw]");
  s.live.mount.pose = {mount[0], mount[1], mount[2]};
  live.read("upside_down", s.live.mount.upside_down);
  live.read("max_pose_gap_s", s.live.max_pose_gap_s);
  live.read("max_pose_wait_s", s.live.max_pose_wait_s);
  live.read("reliable", s.live.reliable);
  live.requireRange("max_pose_gap_s", s.live.max_pose_gap_s, 1e-4, 60, "0.0001-60 (s)");
  live.requireRange("max_pose_wait_s", s.live.max_pose_wait_s, 0, 60, "0-60 (s)");
  live.rejectUnknownKeys();
  YamlSection playback(config.root, "playback", config.path);
  playback.read("wait_for_subscribers", s.wait_for_subscribers);
  playback.read("wait_timeout_s", s.wait_timeout_s);
  playback.read("exit_at_end", s.exit_at_end);
  playback.read("progress_path", s.progress_path);
  playback.read("wait_notice_s", s.wait_notice_s);
  if (!s.progress_path.empty()) s.progress_path = config.resolvePath(s.progress_path);
  playback.requireRange("wait_for_subscribers", s.wait_for_subscribers, 0, 1000, "an integer 0-1000");
  playback.requireRange("wait_timeout_s", s.wait_timeout_s, 0, 86400, "0-86400 (s)");
  playback.requireRange("wait_notice_s", s.wait_notice_s, 0, 86400, "0-86400 (s; 0: never)");
  playback.rejectUnknownKeys();
  return s;
}

}  // namespace scanfilter::ingest
