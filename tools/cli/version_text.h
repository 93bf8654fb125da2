#pragma once
// What `--version` prints for every tool: the kdpm release, the version of each file format it
// reads and writes, and whether this build carries the CUDA backend.
#include <string>

namespace kdpm::cli {

std::string version_text(const std::string& program);

}  // namespace kdpm::cli
