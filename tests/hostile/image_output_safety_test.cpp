// Images and AOVs go through the same output discipline as container files: a full disk is an
// error (not a truncated PNG/BMP over a good one), a planted link at the old predictable
// temporary name redirects nothing, and a failed AOV leaves the main image as it was.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "runtime/render/image/image_output.h"
#include "tests/hostile/fork_child.h"
#include "tests/support/file_contents.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

// Noise compresses badly, so the encoded file is large.
Image noise(int w, int h) {
    Image img(w, h);
    std::uint32_t s = 12345;
    for (float& v : img.rgb) {
        s = s * 1664525u + 1013904223u;
        v = static_cast<float>(s >> 8) / 16777216.0f;
    }
    return img;
}

std::vector<fs::path> write_png(const fs::path& dest, const Image& img, const AovImages* aovs = nullptr,
                                AovSet set = {}) {
    FrameOutput f{&img, &img, aovs, set};
    return write_frame(dest, f);
}

}  // namespace

TEST_CASE("a full disk while writing a PNG or BMP is an error and keeps the old image", "[hostile][output][image]") {
    for (const char* name : {"out.png", "out.bmp"}) {
        test::TempDir dir;
        const fs::path dest = dir / name;
        { std::ofstream(dest) << "old image"; }
        const Image img = noise(128, 128);
        const auto end = test::run_in_child([&] {
            ::signal(SIGXFSZ, SIG_IGN);
            struct rlimit lim{8192, 8192};
            ::setrlimit(RLIMIT_FSIZE, &lim);
            try {
                write_png(dest, img);
            } catch (const std::runtime_error&) {
                return 0;
            }
            return 1;
        });
        INFO(name);
        CHECK(end.exit_code == 0);
        CHECK(test::file_contents(dest) == "old image");
        CHECK(std::distance(fs::directory_iterator(dir.path()), fs::directory_iterator()) == 1);
    }
}

TEST_CASE("a link planted at a predictable temporary name redirects no image write", "[hostile][output][image]") {
    test::TempDir dir;
    { std::ofstream(dir / "victim") << "precious"; }
    // The name the old writer used: .STEM.tmpPID.EXT
    fs::create_symlink(dir / "victim", dir / (".out.tmp" + std::to_string(::getpid()) + ".png"));
    write_png(dir / "out.png", noise(8, 8));
    CHECK(test::file_contents(dir / "victim") == "precious");
    CHECK(fs::file_size(dir / "out.png") > 0);
}

TEST_CASE("a failed AOV write leaves the main image untouched", "[hostile][output][image]") {
    test::TempDir dir;
    { std::ofstream(dir / "out.png") << "old image"; }
    fs::create_directory(dir / "out.depth.exr");  // the AOV cannot be written
    const Image img = noise(8, 8);
    AovImages aovs;
    aovs.depth.assign(img.pixel_count(), 1.0f);
    AovSet set;
    set.depth = true;
    CHECK_THROWS(write_png(dir / "out.png", img, &aovs, set));
    CHECK(test::file_contents(dir / "out.png") == "old image");
}

TEST_CASE("an image written through a symlink replaces the link's target", "[hostile][output][image]") {
    test::TempDir dir;
    { std::ofstream(dir / "real.png") << "old image"; }
    fs::create_symlink("real.png", dir / "link.png");
    write_png(dir / "link.png", noise(8, 8));
    CHECK(fs::is_symlink(dir / "link.png"));
    CHECK(test::file_contents(dir / "real.png") != "old image");
}
