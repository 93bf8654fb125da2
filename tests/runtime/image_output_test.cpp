// Frames written with OpenImageIO: PNG gets the display image and AOVs as separate EXRs, EXR
// gets linear radiance plus AOV channels; failures leave no file behind.
#include <catch2/catch.hpp>

#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "runtime/render/image/image_output.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

namespace {

struct Frame {
    Image linear{2, 1}, display{2, 1};
    AovImages aovs;
    Frame() {
        linear.rgb = {2.0f, 0.5f, 0.25f, 0.0f, 0.0f, 0.0f};
        display.rgb = {1.0f, 0.5f, 0.0f, 0.0f, 0.0f, 1.0f};
        aovs.depth = {1.5f, std::numeric_limits<float>::infinity()};
        aovs.triangle = {7, -1};
    }
};

std::vector<float> read_pixels(const std::filesystem::path& p, OIIO::ImageSpec& spec) {
    auto in = OIIO::ImageInput::open(p.string());
    REQUIRE(in);
    spec = in->spec();
    std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
    REQUIRE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
    return px;
}

}  // namespace

TEST_CASE("a PNG holds the display image and AOVs go to separate EXR files", "[output]") {
    test::TempDir dir;
    Frame f;
    AovSet set;
    set.depth = set.triangle = true;
    auto written = write_frame(dir / "out.png", FrameOutput{&f.linear, &f.display, &f.aovs, set});
    REQUIRE(written.size() == 3);
    OIIO::ImageSpec spec;
    auto px = read_pixels(dir / "out.png", spec);
    CHECK(spec.nchannels == 3);
    CHECK(px[0] == 1.0f);
    CHECK(px[1] == Approx(128.0f / 255.0f).margin(1.0 / 255));
    auto tri = read_pixels(dir / "out.triangle.exr", spec);
    CHECK(tri[0] == 7.0f);
    CHECK(tri[1] == -1.0f);
    auto depth = read_pixels(dir / "out.depth.exr", spec);
    CHECK(depth[0] == 1.5f);
    CHECK(std::isinf(depth[1]));
    // No temporary files remain.
    std::size_t files = 0;
    for (auto& e : std::filesystem::directory_iterator(dir.path())) files += e.is_regular_file();
    CHECK(files == 3);
}

TEST_CASE("an EXR holds linear radiance with the AOVs as extra channels", "[output]") {
    test::TempDir dir;
    Frame f;
    AovSet set;
    set.depth = set.triangle = true;
    auto written = write_frame(dir / "out.exr", FrameOutput{&f.linear, &f.display, &f.aovs, set});
    REQUIRE(written.size() == 1);
    OIIO::ImageSpec spec;
    auto px = read_pixels(dir / "out.exr", spec);
    REQUIRE(spec.nchannels == 5);
    int z = spec.channelindex("Z"), t = spec.channelindex("triangle");
    REQUIRE(z >= 0);
    REQUIRE(t >= 0);
    CHECK(px[0] == 2.0f);
    CHECK(px[static_cast<std::size_t>(z)] == 1.5f);
    CHECK(px[static_cast<std::size_t>(spec.nchannels + t)] == -1.0f);
}

TEST_CASE("a failed write throws and leaves no file", "[output]") {
    test::TempDir dir;
    Frame f;
    CHECK_THROWS(write_frame(dir / "missing-folder" / "out.png", FrameOutput{&f.linear, &f.display, nullptr, {}}));
    CHECK_THROWS(write_frame(dir / "out.unknownext", FrameOutput{&f.linear, &f.display, nullptr, {}}));
    CHECK(std::filesystem::is_empty(dir.path()));
}
