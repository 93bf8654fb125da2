#pragma once
// Wraps a tool's body: any error becomes "PROGRAM: error: REASON" on one line and exit code 1.
#include <functional>

namespace kdpm::cli {

int run_tool(const char* program, const std::function<int()>& body);

}  // namespace kdpm::cli
