#pragma once
// kdpm-bench-quality's output: per scene the error-against-time table of every ladder, the
// equal-time comparison (each mode's best rung within the budget) and the verdicts.
#include <string>
#include <vector>

#include "tools/bench/quality_bench.h"

namespace kdpm::bench {

std::string format_quality_report(const std::vector<QualityResult>& results, bool markdown);

// The rung with the lowest relMSE among those that took at most `seconds`; null when none did.
const Rung* best_within(const Ladder& ladder, double seconds);

}  // namespace kdpm::bench
