#pragma once
// Small writers of hostile inputs for the end-to-end tests.
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/run_command.h"

namespace kdpm::test {

inline void write_file(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

// A tool's run that must end with a one-line error and exit code 1 (not a crash or a hang).
inline bool is_clean_error(const CommandResult& r) {
    return r.exit_code == 1 && r.output.find("error:") != std::string::npos &&
           r.output.find('\n') == r.output.size() - 1;
}

// One triangle in ASCII PLY whose face lists `third` as its last vertex index.
inline std::string ply_triangle(long third) {
    return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 " +
           std::to_string(third) + "\n";
}

// A scene card around `mesh` with extra members (JSON text without braces, may be empty).
inline std::string card_json(const std::string& mesh, const std::string& extra = "") {
    return "{\"mesh\": \"" + mesh + "\"" + (extra.empty() ? "" : ", " + extra) + "}";
}

}  // namespace kdpm::test
