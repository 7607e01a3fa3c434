#include <iostream>

#include "commands.hpp"
#include "scanfilter/scan_renderer.hpp"
#include "scanfilter/scan_source.hpp"

namespace scanfilter::cli {

int runRender(const RenderOptionsCli& options) {
  auto source = openScanSource(options.input);
  ScanRenderer renderer;
  ScanRecord record;
  for (int index = 0; source->next(record); ++index) {
    if (index < options.first_frame) continue;
    if (options.frames > 0 && index >= options.first_frame + options.frames) break;
    renderer.add(record.scan, source->header().sensor, record.scan.labels);
  }
  renderer.save(options.output, {.panel_pixels = options.pixels, .title = options.title.empty() ? options.input : options.title});
  std::cout << "drew " << renderer.pointCount() << " points -> " << options.output << "\n";
  return 0;
}

}  // namespace scanfilter::cli
