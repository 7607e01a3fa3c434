// The Mines URG-04LX log reader on arbitrary bytes, and the content sniffing
// that picks a reader for a file (openScanSource), as every tool opens logs.
#include "fuzz_input.hpp"
#include "scanfilter/mines_log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = scanfilter::fuzz::writeInput(data, size, "input.dat");
  scanfilter::fuzz::expectInputError([&] {
    scanfilter::MinesLogReader reader(path);
    scanfilter::ScanRecord record;
    while (reader.next(record)) {
    }
  });
  scanfilter::fuzz::expectInputError([&] {
    auto source = scanfilter::openScanSource(path);
    scanfilter::ScanRecord record;
    while (source->next(record)) {
    }
  });
  return 0;
}
