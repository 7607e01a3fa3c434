#pragma once
// The DDS tools' --namespace, checked as the services check theirs.
#include <string>

#include <CLI/CLI.hpp>

#include "scanfilter/dds/topic_names.hpp"

namespace scanfilter::dds_io {

inline const CLI::Validator kNamespaceCheck(
    [](std::string& ns) -> std::string {
      const auto problem = topicNamespaceProblem(ns);
      return problem ? *problem : std::string();
    },
    "NAME");

}  // namespace scanfilter::dds_io
