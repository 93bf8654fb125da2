// Every tool answers --version with the kdpm release, the file format versions and whether the
// CUDA backend is built, and exits 0.
#include <catch2/catch.hpp>

#include <filesystem>

#include "formats/file_kind.h"
#include "formats/metadata.h"
#include "tests/support/run_command.h"

using namespace kdpm;

TEST_CASE("every tool prints its version, the file formats and the backends", "[tools][version]") {
    const std::string geometry_version = std::to_string(file_kind_info(FileKind::geometry).major) + "." +
                                         std::to_string(file_kind_info(FileKind::geometry).minor);
    for (const char* tool : {"kdpm-build-geometry", "kdpm-shoot-photons", "kdpm-build-photons", "kdpm-render",
                             "kdpm-view", "kdpm-inspect", "kdpm-validate", "kdpm-bench", "kdpm-bench-build",
                             "kdpm-bench-photons", "kdpm-bench-quality"}) {
        if (!std::filesystem::exists(test::tool_path(tool))) {
            WARN(tool << " is not built here");
            continue;
        }
        const auto r = test::run_tool(std::string(tool) + " --version");
        INFO(tool << ": " << r.output);
        CHECK(r.exit_code == 0);
        CHECK(r.output.rfind(std::string(tool) + " (kdpm) " + kdpm_version() + "\n", 0) == 0);
        CHECK_THAT(r.output, Catch::Contains(".kdg " + geometry_version) && Catch::Contains(".kdph ") &&
                                 Catch::Contains(".kdp ") && Catch::Contains("CUDA backend: "));
    }
}
