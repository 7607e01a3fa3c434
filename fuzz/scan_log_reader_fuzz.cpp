// The scan log reader (.scanlog.jsonl, plain or gzip) on arbitrary bytes.
#include "fuzz_input.hpp"
#include "scanfilter/scan_log_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = scanfilter::fuzz::writeInput(data, size, "input.scanlog.jsonl");
  scanfilter::fuzz::expectInputError([&] {
    scanfilter::ScanLogReader reader(path);
    scanfilter::ScanRecord record;
    while (reader.next(record)) {
    }
  });
  return 0;
}
