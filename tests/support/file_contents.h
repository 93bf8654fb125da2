#pragma once
// A whole file's bytes as a string, for tests that compare or damage files.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace kdpm::test {

inline std::string file_contents(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace kdpm::test
