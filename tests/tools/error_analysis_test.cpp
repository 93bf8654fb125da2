// kdpm-bench-quality's error analysis: the edge mask finds creases and depth steps and nothing
// else, the split attributes a bias to the region that holds it, the error picture's colours
// follow the sign and size of the log ratio.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "runtime/render/image/post_process.h"
#include "tools/bench/error_analysis.h"

using namespace kdpm;
using namespace kdpm::bench;

namespace {

constexpr int kW = 16, kH = 8;

// A flat wall facing the camera at depth 1, columns x >= 8 replaced as `right` says.
AovImages wall(bool crease, bool step, bool miss) {
    AovImages a;
    a.depth.assign(kW * kH, 1.0f);
    a.normal.assign(3 * kW * kH, 0.0f);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const int p = y * kW + x;
            a.normal[3 * p + 2] = 1.0f;
            if (x < 8) continue;
            if (crease) a.normal[3 * p + 2] = 0.0f, a.normal[3 * p + 0] = 1.0f;
            if (step) a.depth[p] = 1.2f;
            if (miss) a.depth[p] = std::numeric_limits<float>::infinity(), a.normal[3 * p + 2] = 0.0f;
        }
    return a;
}

Image constant(float v) {
    Image image(kW, kH);
    for (float& c : image.rgb) c = v;
    return image;
}

}  // namespace

TEST_CASE("edge_mask marks pixels near creases, depth steps and silhouettes only", "[tools][bench]") {
    const AovImages flat = wall(false, false, false);
    for (std::uint8_t e : edge_mask(flat, kW, kH, 2)) CHECK(e == 0);
    // A gentle curve (10 degrees a pixel) is no edge either.
    AovImages curved = flat;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const float a = 0.17f * static_cast<float>(x - kW / 2) / 8.0f;
            curved.normal[3 * (y * kW + x) + 0] = std::sin(a);
            curved.normal[3 * (y * kW + x) + 2] = std::cos(a);
        }
    for (std::uint8_t e : edge_mask(curved, kW, kH, 2)) CHECK(e == 0);
    for (const AovImages& a : {wall(true, false, false), wall(false, true, false), wall(false, false, true)}) {
        const auto mask = edge_mask(a, kW, kH, 2);
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                // The boundary lies between columns 7 and 8: columns 5..10 are within 2 pixels.
                INFO("x " << x << " y " << y);
                CHECK(static_cast<bool>(mask[y * kW + x]) == (x >= 5 && x <= 10));
            }
    }
}

TEST_CASE("split_error puts a bias near edges into the edge region", "[tools][bench]") {
    const auto mask = edge_mask(wall(true, false, false), kW, kH, 2);
    const Image reference = constant(0.5f);
    Image test = reference;
    for (int p = 0; p < kW * kH; ++p)
        if (mask[p])
            for (int c = 0; c < 3; ++c) test.rgb[3 * p + c] = 0.6f;  // 20 % too bright there
    const RegionSplit split = split_error(test, reference, mask);
    CHECK(split.edges.mean_ratio == Approx(1.2));
    CHECK(split.flat.mean_ratio == Approx(1.0));
    CHECK(split.flat.relmse == 0.0);
    CHECK(split.edges.relmse == Approx(0.01 / (0.25 + 0.01)));
    CHECK(split.edges.error_share == Approx(1.0));
    CHECK(split.edges.share == Approx(6.0 / 16.0));
    CHECK(split.flat.share == Approx(10.0 / 16.0));
}

TEST_CASE("the error picture is red where too bright, blue where too dark, black where equal", "[tools][bench]") {
    const Image reference = constant(0.5f);
    const Image same = log_ratio_image(reference, reference);
    for (float v : same.rgb) CHECK(v == 0.0f);
    const Image bright = log_ratio_image(constant(1.0f), reference);  // +1 stop: full red
    const Image dark = log_ratio_image(constant(0.25f), reference);   // -1 stop: full blue
    const Image slightly = log_ratio_image(constant(0.5f * std::pow(2.0f, 0.25f)), reference);
    for (int p = 0; p < kW * kH; ++p) {
        CHECK(bright.rgb[3 * p] == Approx(1.0f));
        CHECK(bright.rgb[3 * p + 2] == 0.0f);
        CHECK(dark.rgb[3 * p] == 0.0f);
        CHECK(dark.rgb[3 * p + 2] == Approx(1.0f));
        CHECK(slightly.rgb[3 * p] == Approx(0.5f).margin(1e-4));  // a quarter stop: sqrt(0.25)
    }
}

TEST_CASE("side_by_side shows test, reference and error in that order, tone-mapped alike", "[tools][bench]") {
    const Image reference = constant(0.5f), test = constant(1.0f);
    const Image picture = side_by_side(test, reference);
    REQUIRE(picture.width == 3 * kW);
    REQUIRE(picture.height == kH);
    const PostSettings post;
    const float test_display = to_display(expose(test, post), post.tone_map).rgb[0];
    const float reference_display = to_display(expose(reference, post), post.tone_map).rgb[0];
    CHECK(test_display > reference_display);
    for (int y = 0; y < kH; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * 3 * kW * 3;
        CHECK(picture.rgb[row + 3 * 2] == test_display);
        CHECK(picture.rgb[row + 3 * (kW + 2)] == reference_display);
        CHECK(picture.rgb[row + 3 * (2 * kW + 2)] == Approx(1.0f));  // +1 stop, red
    }
}
