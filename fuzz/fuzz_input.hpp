#pragma once
// What every fuzz target shares: the input as a file (the readers and config
// loaders take paths, as the tools and services call them), and the rule that
// bad input may only ever end in an InputError. Any other exception escapes
// LLVMFuzzerTestOneInput and libFuzzer reports it as a crash, as it does every
// sanitizer report.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scanfilter/input_error.hpp"

namespace scanfilter::fuzz {

// A private directory for this fuzzing process (removed at exit), holding
// the side files a config names (fastdds-loopback.xml, filter.yaml).
const std::string& workDirectory();

// Writes the input to `name` in the work directory; returns its path.
std::string writeInput(const std::uint8_t* data, std::size_t size, const std::string& name = "input");

// Runs `body`; an InputError is the expected outcome of bad input.
template <typename Body>
void expectInputError(Body&& body) {
  try {
    body();
  } catch (const InputError&) {
  }
}

}  // namespace scanfilter::fuzz
