// kdpm's own image encoders (the GPU bundle's only ones): a PNG that OpenImageIO reads back
// pixel for pixel, and PFM files whose difference kdpm-image-diff reports exactly.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include <OpenImageIO/imageio.h>

#include "formats/oiio/oiio_plugin_loader.h"
#include "runtime/render/image/image_encoder.h"
#include "runtime/render/image/image_output.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;

TEST_CASE("the built-in PNG encoder writes what OpenImageIO reads back", "[output][builtin]") {
    test::TempDir dir;
    const int w = 7, h = 3;
    std::vector<float> rgb(static_cast<std::size_t>(w) * h * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<float>((i * 37) % 256) / 255.0f;
    rgb[0] = -1.0f;  // clamped to 0
    rgb[1] = 7.0f;   // clamped to 1
    const auto png = dir / "a.png";
    std::vector<std::uint8_t> bytes;
    REQUIRE(encode_builtin_image(bytes, png, w, h, {"R", "G", "B"}, rgb, true).empty());
    std::ofstream(png, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));

    auto in = OIIO::ImageInput::open(png.string());
    REQUIRE(in);
    REQUIRE(in->spec().width == w);
    REQUIRE(in->spec().height == h);
    REQUIRE(in->spec().nchannels == 3);
    std::vector<unsigned char> back(rgb.size());
    REQUIRE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data()));
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        const float c = std::min(1.0f, std::max(0.0f, rgb[i]));
        INFO("value " << i);
        CHECK(back[i] == static_cast<unsigned char>(std::lround(c * 255.0f)));
    }
    CHECK_FALSE(encode_builtin_image(bytes, dir / "b.png", w, h, {"R", "G"}, std::vector<float>(w * h * 2), true).empty());
    CHECK_FALSE(encode_builtin_image(bytes, dir / "c.tif", w, h, {"R", "G", "B"}, rgb, true).empty());
}

TEST_CASE("kdpm's PNG holds the pixels OpenImageIO's PNG writer writes for the same floats", "[output][builtin][oiio]") {
    // kdpm-render writes .png itself (OpenImageIO did before it became a module): every 8-bit
    // level, the values halfway between levels, and values outside [0, 1].
    std::vector<float> rgb;
    for (int k = 0; k <= 255; ++k)
        for (const float v : {k / 255.0f, (k + 0.5f) / 255.0f, std::nextafter((k + 0.5f) / 255.0f, 0.0f)}) rgb.push_back(v);
    for (const float v : {-1.0f, -0.0f, 1.5f, 1e30f}) rgb.push_back(v);
    while (rgb.size() % 3 != 0) rgb.push_back(0.25f);
    const int w = static_cast<int>(rgb.size() / 3), h = 1;

    test::TempDir dir;
    std::vector<std::uint8_t> ours, theirs;
    REQUIRE(encode_builtin_image(ours, dir / "ours.png", w, h, {"R", "G", "B"}, rgb, true).empty());
    OiioImageRequest request;
    request.destination = (dir / "theirs.png").string();
    request.temp_path = (dir / "theirs.tmp").string();
    request.width = w;
    request.height = h;
    request.channel_names = {"R", "G", "B"};
    request.pixels = rgb.data();
    request.eight_bit = true;
    REQUIRE(oiio_plugin().encode(request, theirs).empty());
    REQUIRE(!theirs.empty());
    auto decode = [&](const std::vector<std::uint8_t>& bytes, const char* name) {
        std::ofstream(dir / name, std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        auto in = OIIO::ImageInput::open((dir / name).string());
        REQUIRE(in);
        REQUIRE(in->spec().width == w);
        std::vector<unsigned char> pixels(rgb.size());
        REQUIRE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
        return pixels;
    };
    const auto a = decode(ours, "ours.png"), b = decode(theirs, "theirs.png");
    for (std::size_t i = 0; i < rgb.size(); ++i) {
        INFO("value " << rgb[i]);
        CHECK(int{a[i]} == int{b[i]});
    }
}

TEST_CASE("kdpm-image-diff reports the difference of two PFM frames", "[output][builtin]") {
    test::TempDir dir;
    Image a(3, 2), b(3, 2);
    for (std::size_t i = 0; i < a.rgb.size(); ++i) a.rgb[i] = b.rgb[i] = static_cast<float>(i);
    b.rgb[4] += 0.5f;   // one value off by 0.5 ...
    b.rgb[17] -= 2.0f;  // ... and one by 2: mean 2.5 / 18
    for (auto* img : {&a, &b}) {
        FrameOutput f{img, img, nullptr, AovSet{}};
        write_frame(dir / (img == &a ? "a.pfm" : "b.pfm"), f);
    }
    auto same = test::run_tool("kdpm-image-diff " + (dir / "a.pfm").string() + " " + (dir / "a.pfm").string());
    INFO(same.output);
    CHECK(same.exit_code == 0);
    CHECK(same.output.find("mean |diff| 0, max |diff| 0, mean value 8.5, 0 of 18 values differ") != std::string::npos);
    auto differ = test::run_tool("kdpm-image-diff " + (dir / "a.pfm").string() + " " + (dir / "b.pfm").string());
    INFO(differ.output);
    CHECK(differ.exit_code == 0);
    CHECK(differ.output.find("mean |diff| 0.138889, max |diff| 2, mean value 8.5, 2 of 18 values differ") !=
          std::string::npos);
    auto missing = test::run_tool("kdpm-image-diff " + (dir / "a.pfm").string() + " " + (dir / "none.pfm").string());
    CHECK(missing.exit_code != 0);
    CHECK(missing.output.find("cannot open") != std::string::npos);
}
