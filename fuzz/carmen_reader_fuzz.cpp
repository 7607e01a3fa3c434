// The CARMEN log reader (FLASER / ROBOTLASER1, plain or gzip) on arbitrary bytes.
#include "fuzz_input.hpp"
#include "scanfilter/carmen_log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = scanfilter::fuzz::writeInput(data, size, "input.log");
  scanfilter::fuzz::expectInputError([&] {
    scanfilter::CarmenLogReader reader(path, {});
    scanfilter::ScanRecord record;
    while (reader.next(record)) {
    }
  });
  return 0;
}
