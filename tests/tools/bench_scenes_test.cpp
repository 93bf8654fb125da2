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

TEST_CASE("kdpm-bench and kdpm-bench-build build with the SAH costs given, and refuse absurd ones", "[tools][bench]") {
    test::TempDir dir;
    const std::string work = (dir / "work").string();
    fs::create_directories(work);
    const std::string bench = "kdpm-bench --scenes cornell-box --frames 1 --photons 2000 --size 16 --no-peers --quick "
                              "--quiet --repo " + test::source_path("") + " --work " + work;

    const auto costly = test::run_tool(bench + " --intersection-cost 0.75 --empty-bonus 0.5 --traversal-cost 2");
    INFO(costly.output);
    REQUIRE(costly.exit_code == 0);
    CHECK_THAT(costly.output, Catch::Contains("geometry SAH costs: traversal / intersection / empty bonus") &&
                                  Catch::Contains("2 / 0.75 / 0.5"));
    // The scene the bench traced is the one built with those costs: its file says so.
    const auto inspected = test::run_tool("kdpm-inspect " + work + "/cornell-box.kdg --json");
    INFO(inspected.output);
    CHECK_THAT(inspected.output, Catch::Contains("\"intersection_cost\": \"0.75\"") &&
                                     Catch::Contains("\"empty_bonus\": \"0.5\"") &&
                                     Catch::Contains("\"traversal_cost\": \"2\""));

    for (const char* bad : {" --intersection-cost 0", " --empty-bonus 1.5", " --traversal-cost -1"}) {
        const auto refused = test::run_tool(bench + bad);
        INFO(bad << ": " << refused.output);
        CHECK(refused.exit_code != 0);
        CHECK_THAT(refused.output, Catch::Contains("error:") && Catch::Contains("out of range"));
    }
    // The shipped Cornell box only (no shared scenes where KDPM_SCENES points).
    const std::string build_bench_command =
        "KDPM_SCENES='" + (dir / "none").string() + "' " + test::tool_path("kdpm-bench-build") + " --runs 1";
    const auto build_bench = test::run_shell(build_bench_command + " --intersection-cost 0.75");
    INFO(build_bench.output);
    CHECK(build_bench.exit_code == 0);
    CHECK_THAT(build_bench.output, Catch::Contains("SAH costs: traversal 1, intersection 0.75, empty bonus 0.2"));
    const auto refused_build = test::run_shell(build_bench_command + " --empty-bonus 2");
    CHECK(refused_build.exit_code != 0);
}

TEST_CASE("kdpm-bench traces the shooting's bounce rays through kdpm and Embree to the same hits", "[tools][bench]") {
    const auto run = test::run_tool("kdpm-bench --scenes cornell-box --frames 1 --photons 4000 --size 16 --quick --quiet "
                                    "--repo " + test::source_path(""));
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    if (run.output.find("Embree not installed") != std::string::npos) {
        WARN("Embree 3 is not installed (Debian package libembree-dev): no bounce-ray row: skipped");
        return;
    }
    // "<n> photon bounce rays (from the stored hits, path order) vs rtcIntersect1 (<fraction> same hit)"
    const std::string row = " photon bounce rays (from the stored hits, path order) vs rtcIntersect1 (";
    const std::size_t at = run.output.find(row);
    REQUIRE(at != std::string::npos);
    std::size_t line = run.output.rfind('\n', at);
    line = line == std::string::npos ? 0 : line + 1;
    const long rays = std::stol(run.output.substr(line, at - line));
    const double same = std::stod(run.output.substr(at + row.size()));
    CHECK(rays >= 2000);  // a ray per stored hit of 4000 paths in a closed box
    CHECK(same >= 0.999);
}
