#pragma once
#include <ostream>

#include "scanfilter/removal_score.hpp"

namespace scanfilter::cli {

// Prints counts per code and, when the log had truth, the accuracy table.
void printScoreReport(std::ostream& out, const RemovalScore& score);

}  // namespace scanfilter::cli
