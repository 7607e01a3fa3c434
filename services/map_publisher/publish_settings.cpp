#include "publish_settings.hpp"

#include <filesystem>

#include "scanfilter/yaml_section.hpp"

namespace scanfilter::map_service {

PublishSettings readPublishSettings(const dds_io::ServiceConfigFile& config) {
  PublishSettings s;
  YamlSection section(config.root, "publishing", config.path);
  section.read("rate_hz", s.rate_hz);
  section.read("frame_id", s.frame_id);
  section.read("save_path", s.save_path);
  section.read("save_period_s", s.save_period_s);
  section.read("load_on_start", s.load_on_start);
  section.requireRange("rate_hz", s.rate_hz, 0.01, 100, "0.01-100 (Hz)");
  section.requireRange("save_period_s", s.save_period_s, 0.1, 1e6, "a value >= 0.1 (s)");
  section.rejectUnknownKeys();
  s.save_path = config.resolvePath(s.save_path);
  // A typo in the folder would show only at the first save, a period later.
  const std::filesystem::path base(s.save_path);
  if (!s.save_path.empty() && base.has_parent_path())
    section.requireFolder("save_path", base.parent_path().string(),
                          " (the map is saved as " + base.filename().string() + ".pgm/.yaml/.png in it)");
  return s;
}

}  // namespace scanfilter::map_service
