// kdpm-bench finds scenes/ from the working directory (or a parent) when its executable lives
// elsewhere, and says which option to pass when it finds none.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

test::CommandResult run_in(const fs::path& cwd, const std::string& command) {
    return test::run_shell("cd '" + cwd.string() + "' && " + command);
}

}  // namespace

TEST_CASE("kdpm-bench finds scenes/ from the working directory", "[tools][bench]") {
    test::TempDir dir;
    // A copy of the executable outside the source tree, so only the working directory can lead to scenes/.
    fs::create_directories(dir / "elsewhere" / "bin");
    const fs::path bench = dir / "elsewhere" / "bin" / "kdpm-bench";
    fs::copy_file(test::tool_path("kdpm-bench"), bench);
    const std::string quick = bench.string() + " --scenes cornell-box --frames 1 --photons 2000 --size 16 --no-peers --quick --quiet";

    const auto lost = run_in(dir.path(), quick);
    INFO(lost.output);
    CHECK(lost.exit_code == 1);
    CHECK_THAT(lost.output, Catch::Contains("cannot find the scenes/ folder") && Catch::Contains("--repo"));

    fs::create_directories(dir / "project" / "scenes" / "cornell-box" / "deeper");
    fs::copy(test::source_path("scenes/cornell-box"), dir / "project" / "scenes" / "cornell-box");
    const auto found = run_in(dir / "project" / "scenes" / "cornell-box" / "deeper", quick);
    INFO(found.output);
    CHECK(found.exit_code == 0);
    CHECK_THAT(found.output, Catch::Contains("cornell-box"));
    // The full frame in every lighting mode, and the viewer's frame rate.
    for (const char* row : {"\ndirect ", "\nphotons ", "\ndirect+photons ", "\npath ", "cache on", "cache off", "\nsppm "})
        CHECK_THAT(found.output, Catch::Contains("full frame per mode") && Catch::Contains(row));
    CHECK_THAT(found.output, Catch::Contains("viewer frame (kdpm-view at rest: photons, k=32"));

    const auto given = run_in(dir.path(), quick + " --repo " + (dir / "project").string());
    INFO(given.output);
    CHECK(given.exit_code == 0);
}
