#pragma once
// The filters of `scanfilter bench-accuracy`: ours (defaults from
// config/filter.yaml) and the baselines. docs/baselines.md says where each
// default comes from.
#include <vector>

#include "scanfilter/accuracy/filter_family.hpp"
#include "scanfilter/filter_config.hpp"

namespace scanfilter::accuracy {

// Our filter (from `ours`, usually config/filter.yaml) and the five baselines.
std::vector<FilterFamily> comparisonFamilies(const FilterConfig& ours);

}  // namespace scanfilter::accuracy
