#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>

#include "runtime/view/frame_composer.h"

using namespace kdpm;

namespace {

RenderResult two_pixel_frame() {
    RenderResult r;
    r.linear = Image(2, 1);
    r.linear.rgb = {0.5f, 0.5f, 0.5f, 2.0f, 2.0f, 2.0f};
    r.aovs.depth = {1.0f, 3.0f};
    r.aovs.normal = {0.0f, 0.0f, 1.0f, 0.0f, 1.0f, 0.0f};
    return r;
}

}  // namespace

TEST_CASE("frame composer shaded view equals kdpm-render's post-processing", "[view][composer]") {
    RenderResult r = two_pixel_frame();
    ViewOptions o;
    o.exposure_stops = 1.0f;
    o.tone_map = ToneMap::reinhard;
    PostSettings post;
    post.exposure_stops = 1.0f;
    post.tone_map = ToneMap::reinhard;
    CHECK(compose_view(r, {}, o).rgb == to_display(expose(r.linear, post), ToneMap::reinhard).rgb);
}

TEST_CASE("frame composer shows the renderer's own display image when made with the view's settings",
          "[view][composer]") {
    RenderResult r = two_pixel_frame();
    r.post.exposure_stops = 1.0f;
    r.post.tone_map = ToneMap::reinhard;
    r.exposed = expose(r.linear, r.post);
    r.display = to_display(r.exposed, r.post.tone_map);
    ViewOptions o;
    o.exposure_stops = 1.0f;
    o.tone_map = ToneMap::reinhard;
    CHECK(compose_view(r, {}, o).rgb == r.display.rgb);
    // Marked, to tell a reuse from a recomposition: reused while the settings agree...
    r.display.rgb[0] = 0.25f;
    CHECK(compose_view(r, {}, o).rgb[0] == 0.25f);
    // ...recomposed from the radiance once the view's exposure or tone map differ, or with bloom.
    o.exposure_stops = 2.0f;
    PostSettings now;
    now.exposure_stops = 2.0f;
    now.tone_map = ToneMap::reinhard;
    CHECK(compose_view(r, {}, o).rgb == to_display(expose(r.linear, now), ToneMap::reinhard).rgb);
    o.exposure_stops = 1.0f;
    o.tone_map = ToneMap::aces;
    CHECK(compose_view(r, {}, o).rgb[0] != 0.25f);
    o.tone_map = ToneMap::reinhard;
    r.post.bloom = true;
    CHECK(compose_view(r, {}, o).rgb[0] != 0.25f);
}

TEST_CASE("frame composer depth and normal views", "[view][composer]") {
    RenderResult r = two_pixel_frame();
    ViewOptions o;
    o.view = ViewKind::depth;
    Image d = compose_view(r, {}, o);
    CHECK(d.rgb[0] > d.rgb[3]);  // nearer is brighter
    r.aovs.depth[1] = std::numeric_limits<float>::infinity();
    d = compose_view(r, {}, o);
    CHECK(d.rgb[3] == 0.0f);  // a miss is black
    o.view = ViewKind::normal;
    Image n = compose_view(r, {}, o);
    CHECK(n.rgb == std::vector<float>{0.5f, 0.5f, 1.0f, 0.5f, 1.0f, 0.5f});
    // A frame without the view's AOV (rendered for another view) is shown shaded meanwhile.
    RenderResult bare = two_pixel_frame();
    bare.aovs = AovImages{};
    ViewOptions shaded;
    o.view = ViewKind::depth;
    CHECK(compose_view(bare, {}, o).rgb == compose_view(bare, {}, shaded).rgb);
    o.view = ViewKind::normal;
    CHECK(compose_view(bare, {}, o).rgb == compose_view(bare, {}, shaded).rgb);
    CHECK(compose_view(bare, {}, o).rgb != n.rgb);
    o.view = ViewKind::photon_density;
    Image p = compose_view(r, {100.0f, 0.0f}, o);
    CHECK(p.rgb[0] + p.rgb[1] + p.rgb[2] > 0.0f);
    CHECK(p.rgb[3] + p.rgb[4] + p.rgb[5] == 0.0f);  // no photons: black
}

TEST_CASE("frame composer scales previews by pixel replication and rounds to 8 bits", "[view][composer]") {
    Image small(2, 1);
    small.rgb = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
    Image big = resize_nearest(small, 4, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            CHECK(big.rgb[(static_cast<std::size_t>(y) * 4 + x) * 3] == (x < 2 ? 0.1f : 0.4f));
    std::vector<unsigned char> bytes;
    Image edge(1, 1);
    edge.rgb = {-1.0f, 0.5f, std::numeric_limits<float>::quiet_NaN()};
    to_rgb8(edge, bytes);
    CHECK(bytes == std::vector<unsigned char>{0, 128, 0});
    CHECK(heat_color(0.0f) == glm::vec3(0.0f));
    CHECK(heat_color(1.0f) == glm::vec3(1.0f));
}

TEST_CASE("8-bit conversion rounds as lround does, halfway cases included", "[view][composer]") {
    // Every float in [0, 1] with the low 8 mantissa bits clear, plus the values nearest each
    // halfway point k + 0.5 of the 255 steps.
    Image values(1, 1);
    values.rgb.clear();
    for (std::uint32_t bits = 0; bits <= 0x3f800000u; bits += 256) {
        float v;
        std::memcpy(&v, &bits, sizeof v);
        values.rgb.push_back(v);
    }
    for (int k = 0; k < 255; ++k) {
        const float half = (static_cast<float>(k) + 0.5f) / 255.0f;
        for (float v : {std::nextafter(half, 0.0f), half, std::nextafter(half, 1.0f)}) values.rgb.push_back(v);
    }
    while (values.rgb.size() % 3 != 0) values.rgb.push_back(1.0f);
    values.width = static_cast<int>(values.rgb.size() / 3);
    std::vector<unsigned char> bytes;
    to_rgb8(values, bytes);
    REQUIRE(bytes.size() == values.rgb.size());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < bytes.size(); ++i)
        differ += bytes[i] != static_cast<unsigned char>(std::lround(values.rgb[i] * 255.0f));
    CHECK(differ == 0);
}

TEST_CASE("density legend scale spans the shown frame's 1st to 99th percentile", "[view][composer]") {
    std::vector<float> density;
    for (int i = 1; i <= 1000; ++i) density.push_back(static_cast<float>(i));
    density.push_back(0.0f);  // a miss: no density
    const DensityScale scale = density_scale(density);
    REQUIRE(scale.valid);
    CHECK(std::exp(scale.log_lo) == Approx(11.0f).epsilon(1e-5));
    CHECK(std::exp(scale.log_hi) == Approx(990.0f).epsilon(1e-5));
    CHECK(density_scale_position(scale, scale.log_lo) == Approx(0.1f));
    CHECK(density_scale_position(scale, scale.log_hi) == Approx(1.0f));
    CHECK_FALSE(density_scale({0.0f, -1.0f}).valid);
}
