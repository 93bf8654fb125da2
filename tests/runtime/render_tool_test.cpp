// kdpm-render end to end: a truncated or corrupted tree file, a missing photon map, a missing
// CUDA device and an unwritable output each give a one-line error (never a crash or a partial
// file); --backend auto falls back to the CPU with a notice.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "tests/support/file_contents.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

void spill(const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary);
    out << bytes;
}

std::filesystem::path build_cornell(const test::TempDir& dir) {
    auto kdg = dir / "scene.kdg";
    auto r = test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                            " -o " + kdg.string() + " --quiet");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return kdg;
}

// One "kdpm-render: error: ..." line, after at most the backend's fallback notice.
bool one_error_line(std::string output) {
    if (output.rfind("kdpm-render: no CUDA device", 0) == 0) output.erase(0, output.find('\n') + 1);
    return output.rfind("kdpm-render: error: ", 0) == 0 && output.find('\n') == output.size() - 1;
}

}  // namespace

TEST_CASE("kdpm-render renders direct light to a PNG and prints the stage table", "[render][tools]") {
    test::TempDir dir;
    auto kdg = build_cornell(dir);
    auto r = test::run_tool("kdpm-render " + kdg.string() + " --mode direct --width 32 --height 24 --backend cpu -o " +
                            (dir / "a.png").string());
    INFO(r.output);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.output, Catch::Contains("ray tracing") && Catch::Contains("photon gather") &&
                             Catch::Contains("shading") && Catch::Contains("post") && Catch::Contains("total"));
    CHECK(std::filesystem::file_size(dir / "a.png") > 100);
    auto q = test::run_tool("kdpm-render " + kdg.string() + " --mode direct --width 8 --quiet -o " +
                            (dir / "b.exr").string());
    CHECK(q.exit_code == 0);
    CHECK(q.output.empty());
}

TEST_CASE("a truncated or corrupted tree file gives a one-line error", "[render][tools]") {
    test::TempDir dir;
    auto kdg = build_cornell(dir);
    const std::string bytes = test::file_contents(kdg);
    auto truncated = dir / "truncated.kdg", corrupted = dir / "corrupted.kdg", garbage = dir / "garbage.kdg";
    spill(truncated, bytes.substr(0, bytes.size() / 2));
    std::string flipped = bytes;
    for (std::size_t i = 200; i < 260 && i < flipped.size(); ++i) flipped[i] = static_cast<char>(flipped[i] ^ 0x5a);
    spill(corrupted, flipped);
    spill(garbage, std::string(4096, '\x7f'));
    for (const auto& bad : {truncated, corrupted, garbage, dir / "missing.kdg"}) {
        auto out = dir / "out.png";
        auto r = test::run_tool("kdpm-render " + bad.string() + " --mode direct --width 8 -o " + out.string());
        INFO(bad << ": " << r.output);
        CHECK(r.exit_code == 1);
        CHECK(one_error_line(r.output));
        CHECK_FALSE(std::filesystem::exists(out));
    }
    // The geometry file given where the photon map belongs is refused too.
    auto r = test::run_tool("kdpm-render " + kdg.string() + " " + kdg.string() + " -o " + (dir / "x.png").string());
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK(one_error_line(r.output));
}

TEST_CASE("photon modes without a photon map and unwritable outputs are one-line errors", "[render][tools]") {
    test::TempDir dir;
    auto kdg = build_cornell(dir);
    auto r = test::run_tool("kdpm-render " + kdg.string() + " --mode photons --width 8 -o " + (dir / "a.png").string());
    INFO(r.output);
    CHECK(r.exit_code == 1);
    CHECK(one_error_line(r.output));
    auto w = test::run_tool("kdpm-render " + kdg.string() + " --mode direct --width 8 -o " +
                            (dir / "no" / "such" / "a.png").string());
    INFO(w.output);
    CHECK(w.exit_code == 1);
    CHECK(one_error_line(w.output));
    auto bad = test::run_tool("kdpm-render " + kdg.string() + " --mode sideways -o " + (dir / "a.png").string());
    CHECK(bad.exit_code == 2);
}

TEST_CASE("backend cuda without a device fails clearly and auto falls back with a notice", "[render][tools]") {
    ::setenv("CUDA_VISIBLE_DEVICES", "", 1);  // hides devices on a GPU machine; inherited by the tool
    test::TempDir dir;
    auto kdg = build_cornell(dir);
    auto cuda = test::run_tool("kdpm-render " + kdg.string() + " --mode direct --width 8 --backend cuda -o " +
                               (dir / "a.png").string());
    INFO(cuda.output);
    CHECK(cuda.exit_code == 1);
    CHECK(one_error_line(cuda.output));
    CHECK_THAT(cuda.output, Catch::Contains("no usable CUDA device"));
    auto automatic = test::run_tool("kdpm-render " + kdg.string() + " --mode direct --width 8 --backend auto -o " +
                                    (dir / "b.png").string());
    INFO(automatic.output);
    CHECK(automatic.exit_code == 0);
    CHECK_THAT(automatic.output, Catch::Contains("using the CPU backend"));
    CHECK(std::filesystem::exists(dir / "b.png"));
}
