// kdpm-render and kdpm-view take --eye/--lookat/--up/--vfov: a new view without a rebuilt .kdg.
// An override gives the very image of a .kdg built with that camera in its card; a camera that
// cannot make an image is a one-line error.
#include <catch2/catch.hpp>

#include <fstream>

#include "tests/support/file_contents.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

// The shipped Cornell card with another camera, written beside a copy of its mesh.
std::filesystem::path cornell_card(const test::TempDir& dir, const std::string& name, const std::string& camera) {
    for (const char* f : {"cornell-box.obj", "cornell-box.mtl"})
        std::filesystem::copy_file(test::source_path(std::string("scenes/cornell-box/") + f), dir / f,
                                   std::filesystem::copy_options::skip_existing);
    const auto card = dir / (name + ".json");
    std::ofstream(card) << R"({ "mesh": "cornell-box.obj", "up": "y", "camera": )" << camera << " }";
    return card;
}

std::filesystem::path build(const test::TempDir& dir, const std::filesystem::path& card) {
    auto kdg = dir / (card.stem().string() + ".kdg");
    auto r = test::run_tool("kdpm-build-geometry " + card.string() + " -o " + kdg.string() + " --quiet");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return kdg;
}

std::string render(const std::filesystem::path& kdg, const std::filesystem::path& out, const std::string& extra) {
    auto r = test::run_tool("kdpm-render " + kdg.string() + " --mode direct --backend cpu --width 48 --height 32 " +
                            "--light-samples 2 --quiet -o " + out.string() + " " + extra);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return test::file_contents(out);
}

bool one_error_line(const std::string& output, const std::string& program) {
    return output.rfind(program + ": error: ", 0) == 0 && output.find('\n') == output.size() - 1;
}

}  // namespace

TEST_CASE("a camera override renders what a card with that camera renders", "[tools][camera]") {
    test::TempDir dir;
    const auto file_camera = build(dir, cornell_card(dir, "front", R"({ "eye": [0, 1, 3.9], "lookat": [0, 1, 0],
        "up": [0, 1, 0], "vfov": 40, "width": 48, "height": 32 })"));
    const auto side_camera = build(dir, cornell_card(dir, "side", R"({ "eye": [0.6, 1.4, 2.5], "lookat": [-0.3, 0.6, 0],
        "up": [0.1, 1, 0], "vfov": 55, "width": 48, "height": 32 })"));

    const std::string front = render(file_camera, dir / "front.png", "");
    const std::string side = render(side_camera, dir / "side.png", "");
    REQUIRE(front != side);
    CHECK(render(file_camera, dir / "moved.png",
                 "--eye 0.6 1.4 2.5 --lookat -0.3 0.6 0 --up 0.1 1 0 --vfov 55") == side);
    // Only some parts given: the others stay the file's.
    CHECK(render(file_camera, dir / "same.png", "--eye 0 1 3.9 --vfov 40") == front);
    CHECK(render(side_camera, dir / "partly.png", "--vfov 40") != side);
}

TEST_CASE("a camera that cannot make an image is a one-line error", "[tools][camera]") {
    test::TempDir dir;
    const auto kdg = build(dir, cornell_card(dir, "front", R"({ "eye": [0, 1, 3.9], "lookat": [0, 1, 0],
        "up": [0, 1, 0], "vfov": 40, "width": 16, "height": 16 })"));
    struct Case {
        const char* options;
        const char* reason;
    };
    for (const Case& c : {Case{"--eye 0 1 0", "same point"}, Case{"--lookat 0 1 3.9", "same point"},
                          Case{"--up 0 0 -2", "parallel"}, Case{"--up 0 0 0", "zero"},
                          Case{"--eye 0 1e39 3.9", "finite"}}) {
        for (const char* tool : {"kdpm-render", "kdpm-view"}) {
            if (!std::filesystem::exists(test::tool_path(tool))) continue;
            const std::string output = std::string(tool) == "kdpm-view" ? " --frames 1 --screenshot " : " -o ";
            const auto r = test::run_tool(std::string(tool) + " " + kdg.string() + " " + c.options +
                                          " --backend cpu --quiet" + output + (dir / "x.png").string());
            INFO(tool << " " << c.options << ": " << r.output);
            CHECK(r.exit_code != 0);
            CHECK(one_error_line(r.output, tool));
            CHECK_THAT(r.output, Catch::Contains("camera") && Catch::Contains(c.reason));
        }
    }
    for (const char* bad : {"--vfov 0", "--vfov 180", "--vfov -5", "--vfov nan", "--eye 1 2", "--up 1 x 2"}) {
        const auto r = test::run_tool("kdpm-render " + kdg.string() + " " + bad + " -o " + (dir / "y.png").string());
        INFO(bad << ": " << r.output);
        CHECK(r.exit_code == 2);
        CHECK(one_error_line(r.output, "kdpm-render"));
    }
    CHECK_FALSE(std::filesystem::exists(dir / "x.png"));
    CHECK_FALSE(std::filesystem::exists(dir / "y.png"));
}
