// A frame too large for the machine's memory is refused, with the amount it needs, before any
// buffer is allocated.
#include <catch2/catch.hpp>

#include <sys/resource.h>

#include <cstdio>
#include <filesystem>
#include <cstdlib>
#include <string>

#include "runtime/render/frame_memory.h"
#include "runtime/view/viewer_memory.h"
#include "tests/support/run_command.h"
#include "tests/hostile/fork_child.h"
#include "tests/hostile/hostile_files.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

void build_one_triangle(const std::filesystem::path& kdg) {
    test::write_file(kdg.parent_path() / "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    REQUIRE(test::run_tool("kdpm-build-geometry '" + (kdg.parent_path() / "tri.obj").string() + "' -o '" + kdg.string() +
                           "' --quiet")
                .exit_code == 0);
}

}  // namespace

TEST_CASE("the frame memory estimate covers the buffers and refuses what does not fit", "[hostile][memory]") {
    const std::uint64_t need = frame_memory_bytes(9000, 9000, true, AovSet{});
    CHECK(need > 81000000ull * 250);  // the passes alone keep ~290 bytes per pixel
    CHECK(need < 81000000ull * 1000);
    CHECK_THROWS_WITH(check_frame_memory(9000, 9000, need, 8ull << 30),
                      Catch::Contains("9000x9000 frame needs about") && Catch::Contains("GiB is available"));
    CHECK_NOTHROW(check_frame_memory(512, 512, frame_memory_bytes(512, 512, true, AovSet{}), 8ull << 30));
    CHECK(available_memory_bytes() > 0);
}

TEST_CASE("kdpm-render --width 9000 --height 9000 under a 6 GiB limit says how much it needs", "[hostile][memory]") {
    test::TempDir dir;
    build_one_triangle(dir / "s.kdg");
    test::CommandResult r{};
    const auto end = test::run_in_child([&] {
        struct rlimit lim{6ull << 30, 6ull << 30};
        ::setrlimit(RLIMIT_AS, &lim);
        r = test::run_tool("kdpm-render '" + (dir / "s.kdg").string() + "' --mode direct --width 9000 --height 9000 -o '" +
                           (dir / "o.png").string() + "' --quiet");
        return r.exit_code == 1 && r.output.find("needs about") != std::string::npos ? 0 : 1;
    });
    CHECK(end.exit_code == 0);
}

TEST_CASE("the viewer counts what it keeps beside the frame, and refuses before opening a window", "[hostile][memory]") {
    AovSet aovs;
    aovs.depth = aovs.normal = true;
    const std::uint64_t frame = frame_memory_bytes(4000, 4000, false, aovs);
    const std::uint64_t viewer = viewer_memory_bytes(4000, 4000, false);
    CHECK(viewer >= frame + 16000000ull * 60);  // the shown frame and the display copies: >= 60 bytes per pixel
    CHECK(viewer_memory_bytes(4000, 4000, true) > viewer);

    // A limit the frame alone fits in but the viewer does not: the old check (the renderer's, at
    // the first frame) would let the window open; without a display that is the error it gave.
    test::TempDir dir;
    build_one_triangle(dir / "s.kdg");
    test::CommandResult r{};
    const auto end = test::run_in_child([&] {
        const rlim_t limit = (frame + viewer) / 2;
        struct rlimit lim{limit, limit};
        ::setrlimit(RLIMIT_AS, &lim);
        ::unsetenv("DISPLAY");
        ::unsetenv("WAYLAND_DISPLAY");
        r = test::run_tool("kdpm-view '" +
                           (dir / "s.kdg").string() + "' --width 4000 --height 4000 --frames 1 --quiet");
        const bool ok = r.exit_code == 1 && r.output.find("4000x4000 frame needs about") != std::string::npos;
        if (!ok) std::fprintf(stderr, "kdpm-view exit %d: %s\n", r.exit_code, r.output.c_str());
        return ok ? 0 : 1;
    });
    CHECK(end.exit_code == 0);
}
