#include <iostream>

#include "commands.hpp"
#include "scanfilter/scan_source.hpp"

namespace scanfilter::cli {

int runDiff(const DiffOptions& options) {
  auto a = openScanSource(options.first);
  auto b = openScanSource(options.second);
  ScanRecord ra, rb;
  std::size_t scans = 0, labelled_scans = 0, differing_scans = 0, differing_beams = 0;
  for (;; ++scans) {
    const bool more_a = a->next(ra), more_b = b->next(rb);
    if (!more_a || !more_b) {
      if (more_a != more_b) {
        std::cout << "different lengths: " << (more_a ? options.second : options.first) << " ends after " << scans
                  << " scans\n";
        return 1;
      }
      break;
    }
    if (ra.scan.labels.size() != rb.scan.labels.size()) {
      std::cout << "scan " << scans << ": " << ra.scan.labels.size() << " vs " << rb.scan.labels.size() << " labels\n";
      return 1;
    }
    labelled_scans += !ra.scan.labels.empty();
    std::size_t here = 0;
    for (std::size_t i = 0; i < ra.scan.labels.size(); ++i) here += ra.scan.labels[i] != rb.scan.labels[i];
    if (here > 0 && differing_scans++ == 0)
      std::cout << "first difference: scan " << scans << " (stamp " << ra.scan.stamp.toDecimal() << "), " << here << " beams\n";
    differing_beams += here;
  }
  // Two logs without labels agree in every one of none: that is no agreement.
  if (labelled_scans == 0) {
    std::cerr << "error: " << (scans == 0 ? "neither log holds a scan" : "neither log carries labels")
              << ": nothing to compare (`scanfilter replay -o OUT` writes a labelled log)\n";
    return 2;
  }
  std::cout << scans << " scans compared; " << differing_scans << " differ in " << differing_beams << " labels\n";
  return differing_scans == 0 ? 0 : 1;
}

}  // namespace scanfilter::cli
