// OpenImageIO is a module (formats/oiio) that the tools load only for image formats kdpm does not
// handle itself: no tool links it (its ~250 libraries took half a second at every start), a .png
// needs no module, and a format that needs it fails in one line when it cannot be loaded.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

// Sets an environment variable for the life of the object.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) { ::setenv(name, value.c_str(), 1); }
    ~ScopedEnv() { ::unsetenv(name_); }

private:
    const char* name_;
};

std::string leading_bytes(const fs::path& path, std::size_t n) {
    std::ifstream in(path, std::ios::binary);
    std::string s(n, '\0');
    in.read(s.data(), static_cast<std::streamsize>(n));
    s.resize(static_cast<std::size_t>(in.gcount()));
    return s;
}

}  // namespace

TEST_CASE("no tool links OpenImageIO", "[tools][oiio]") {
    for (const char* tool : {"kdpm-build-geometry", "kdpm-render", "kdpm-view", "kdpm-bench"}) {
        if (!fs::exists(test::tool_path(tool))) {
            WARN(tool << " is not built here");
            continue;
        }
        const std::string dynamic = test::run_shell("readelf -d '" + test::tool_path(tool) + "'").output;
        INFO(tool << ":\n" << dynamic);
        REQUIRE_THAT(dynamic, Catch::Contains("NEEDED"));  // readelf ran and read the file
        CHECK_THAT(dynamic, !Catch::Contains("OpenImageIO"));
    }
}

TEST_CASE("a .png needs no OpenImageIO; an .exr loads it, and fails in one line without it", "[tools][oiio]") {
    test::TempDir dir;
    const fs::path kdg = dir / "cornell.kdg";
    const auto built = test::run_tool("kdpm-build-geometry '" + test::source_path("scenes/cornell-box/cornell-box.json") +
                                      "' -o '" + kdg.string() + "' --quiet");
    REQUIRE(built.exit_code == 0);
    const std::string render = "kdpm-render '" + kdg.string() + "' --mode direct --width 24 --height 16 --quiet -o ";
    {
        ScopedEnv missing("KDPM_OIIO_PLUGIN", (dir / "no-such-module.so").string());
        const auto png = test::run_tool(render + "'" + (dir / "a.png").string() + "'");
        INFO(png.output);
        CHECK(png.exit_code == 0);
        CHECK(leading_bytes(dir / "a.png", 8) == "\x89PNG\r\n\x1a\n");

        const auto exr = test::run_tool(render + "'" + (dir / "a.exr").string() + "'");
        INFO(exr.output);
        CHECK(exr.exit_code != 0);
        CHECK_THAT(exr.output, Catch::Contains("OpenImageIO") && Catch::Contains("no-such-module.so"));
        CHECK(exr.output.find('\n') == exr.output.size() - 1);  // one line
        CHECK_FALSE(fs::exists(dir / "a.exr"));
    }
    const auto exr = test::run_tool(render + "'" + (dir / "a.exr").string() + "'");
    INFO(exr.output);
    CHECK(exr.exit_code == 0);
    CHECK(leading_bytes(dir / "a.exr", 4) == "\x76\x2f\x31\x01");  // OpenEXR's magic number
    // Nothing else was left in the folder (no temporaries of the failed write).
    std::size_t files = 0;
    for (const auto& entry : fs::directory_iterator(dir.path())) files += entry.is_regular_file() ? 1 : 0;
    CHECK(files == 3);  // cornell.kdg, a.png, a.exr
}
