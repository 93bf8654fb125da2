#pragma once
// kdpm-bench's output: plain text for a terminal or Markdown tables (--markdown), with the
// report's figures and the peers' times beside kdpm's, and the targets checked as ratios.
#include <string>
#include <vector>

#include "tools/bench/scene_bench.h"

namespace kdpm::bench {

std::string format_report(const std::vector<SceneBenchResult>& results, bool markdown);

}  // namespace kdpm::bench
