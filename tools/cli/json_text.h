#pragma once
// JSON string quoting for the tools' --json output.
#include <string>

namespace kdpm::cli {

std::string json_string(const std::string& s);

}  // namespace kdpm::cli
