#include <iostream>

#include "commands.hpp"
#include "scanfilter/scan_renderer.hpp"
#include "scanfilter/scan_source.hpp"

namespace scanfilter::cli {

int runRender(const RenderOptionsCli& options) {
  auto source = openScanSource(options.input);
  ScanRenderer renderer;
  ScanRecord record;
  int index = 0;
  for (; source->next(record); ++index) {
    if (index < options.first_frame) continue;
    if (options.frames > 0 && index >= options.first_frame + options.frames) break;
    renderer.add(record.scan, source->header().sensor, record.scan.labels);
  }
  // An empty picture is no picture of the log: say why there is nothing in it.
  if (index <= options.first_frame) {
    std::cerr << "error: " << options.input << " has " << index << " scans; --first-frame " << options.first_frame
              << " is past its last (scans count from 0)\n";
    return 2;
  }
  renderer.save(options.output, {.panel_pixels = options.pixels, .title = options.title.empty() ? options.input : options.title});
  std::cout << "drew " << renderer.pointCount() << " points -> " << options.output << "\n";
  return 0;
}

}  // namespace scanfilter::cli
