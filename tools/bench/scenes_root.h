#pragma once
// Where the benchmarks find scenes/ (the shipped Cornell box and the cards of the shared scenes).
#include <filesystem>
#include <string>

namespace kdpm::bench {

// The folder holding scenes/: `given` (--repo) when not empty, else the working directory or one
// above it, else the source tree around build/bin, else an installed share/kdpm. Throws
// std::runtime_error (one line, naming --repo) when none has scenes/cornell-box.
std::filesystem::path find_scenes_root(const std::string& given, const char* argv0);

}  // namespace kdpm::bench
