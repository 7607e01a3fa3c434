#pragma once
// A service's config file as the service reads it at start: the common
// `service:` section (loadServiceConfig), then the service's own sections.
// Each *_config_fuzz.cpp names the service's sections and reader.
#include <set>
#include <string>

#include "fuzz_input.hpp"
#include "scanfilter/dds/service_config.hpp"

namespace scanfilter::fuzz {

// The config file next to the side files it names by default (filter.yaml,
// fastdds-loopback.xml), as in config/.
template <typename ReadOwnSections>
void fuzzServiceConfig(const std::uint8_t* data, std::size_t size, const std::set<std::string>& own_sections,
                       ReadOwnSections&& read_own) {
  const std::string path = writeInput(data, size, "service-fuzz.yaml");
  expectInputError([&] {
    const dds_io::ServiceConfigFile config = dds_io::loadServiceConfig(path, "127.0.0.1:9470", own_sections);
    read_own(config);
  });
}

}  // namespace scanfilter::fuzz
