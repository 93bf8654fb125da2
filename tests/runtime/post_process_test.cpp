// Exposure, tone curves and the sRGB transfer function against their definitions.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <utility>
#include <vector>

#include "runtime/render/image/image_pool.h"
#include "runtime/render/image/post_process.h"

using namespace kdpm;

TEST_CASE("tone curves map radiance into the unit interval as defined", "[post]") {
    CHECK(tone_map_value(1.0f, ToneMap::reinhard) == Approx(0.5f));
    CHECK(tone_map_value(3.0f, ToneMap::reinhard) == Approx(0.75f));
    CHECK(tone_map_value(0.0f, ToneMap::aces) == Approx(0.0f).margin(1e-6));
    CHECK(tone_map_value(1000.0f, ToneMap::aces) == Approx(1.0f));
    CHECK(tone_map_value(0.18f, ToneMap::aces) > 0.18f * 0.9f);  // mid grey stays near mid grey
    CHECK(tone_map_value(2.0f, ToneMap::none) == 1.0f);
    CHECK(tone_map_value(-1.0f, ToneMap::reinhard) == 0.0f);
}

TEST_CASE("sRGB encoding follows the piecewise standard curve", "[post]") {
    CHECK(srgb_encode(0.0f) == 0.0f);
    CHECK(srgb_encode(1.0f) == Approx(1.0f));
    CHECK(srgb_encode(0.002f) == Approx(12.92f * 0.002f));
    CHECK(srgb_encode(0.5f) == Approx(1.055f * std::pow(0.5f, 1.0f / 2.4f) - 0.055f));
}

TEST_CASE("the sRGB power curve stays within 1e-6 of the standard's pow over every exponent", "[post]") {
    // Every 97th float from the linear segment's end to 1, in double against the definition:
    // the fast x^(1/2.4) covers each binade with its own power-of-two factor.
    std::uint32_t bits;
    const float start = 0.0031308f;
    std::memcpy(&bits, &start, sizeof bits);
    double worst = 0.0;
    for (float x = start; x <= 1.0f; bits += 97, std::memcpy(&x, &bits, sizeof x)) {
        const double exact = 1.055 * std::pow(static_cast<double>(x), 1.0 / 2.4) - 0.055;
        worst = std::max(worst, std::abs(static_cast<double>(srgb_encode(x)) - exact));
    }
    CHECK(worst < 1e-6);
    CHECK(srgb_encode(std::nextafter(0.0031308f, 1.0f)) == Approx(12.92f * 0.0031308f).epsilon(1e-4));  // continuous
    CHECK(srgb_encode(2.0f) == srgb_encode(1.0f));
    CHECK(srgb_encode(-1.0f) == 0.0f);
}

TEST_CASE("exposure scales by powers of two and bloom spreads only bright light", "[post]") {
    Image img(9, 9);
    img.rgb[(4 * 9 + 4) * 3 + 0] = 100.0f;  // one bright red pixel
    img.rgb[0] = 0.5f;
    PostSettings s;
    s.exposure_stops = 1.0f;
    Image e = expose(img, s);
    CHECK(e.rgb[0] == 1.0f);
    CHECK(e.rgb[(4 * 9 + 4) * 3] == 200.0f);

    s.exposure_stops = 0.0f;
    s.bloom = true;
    s.bloom_radius = 0.2f;
    Image b = expose(img, s);
    CHECK(b.rgb[(4 * 9 + 5) * 3 + 0] > 0.0f);   // red glow next to the bright pixel
    CHECK(b.rgb[(4 * 9 + 5) * 3 + 1] == 0.0f);  // no green appears
    CHECK(b.rgb[0] == Approx(0.5f).margin(0.5f * 0.2f));
}

TEST_CASE("display images hold tone-mapped sRGB values", "[post]") {
    Image img(1, 1);
    img.rgb = {1.0f, 0.0f, 3.0f};
    Image d = to_display(img, ToneMap::reinhard);
    CHECK(d.rgb[0] == Approx(srgb_encode(0.5f)));
    CHECK(d.rgb[1] == 0.0f);
    CHECK(d.rgb[2] == Approx(srgb_encode(0.75f)));
}

TEST_CASE("a frame's post-processing in one pass equals exposing, then converting for display", "[post]") {
    Image img(17, 5);
    for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] = 0.001f * static_cast<float>(i * i % 5003);
    img.rgb[7] = NAN;
    img.rgb[8] = INFINITY;
    for (const ToneMap curve : {ToneMap::aces, ToneMap::reinhard, ToneMap::none})
        for (const bool bloom : {false, true}) {
            PostSettings s;
            s.exposure_stops = 0.5f;
            s.tone_map = curve;
            s.bloom = bloom;
            // Outputs that held another, larger image: they are reshaped and wholly rewritten.
            Image exposed(30, 30), display(30, 30);
            for (float& v : display.rgb) v = 7.0f;
            post_process(img, s, exposed, display);
            const Image want_exposed = expose(img, s);
            CHECK(exposed.width == img.width);
            CHECK(exposed.height == img.height);
            CHECK(exposed.rgb == want_exposed.rgb);
            CHECK(display.width == img.width);
            CHECK(display.rgb == to_display(want_exposed, curve).rgb);
        }
}

TEST_CASE("the image pool hands kept storage out again, zeroed, and keeps at most six images", "[post]") {
    ImagePool pool;
    Image a = pool.take(4, 3);
    CHECK(a.rgb.size() == 36);
    for (float& v : a.rgb) v = 5.0f;
    const float* storage = a.rgb.data();
    pool.give(std::move(a));
    CHECK(pool.kept() == 1);
    Image b = pool.take(2, 2);  // smaller: the same storage, only zeros
    CHECK(b.rgb.data() == storage);
    CHECK(b.width == 2);
    CHECK(b.rgb == std::vector<float>(12, 0.0f));
    CHECK(pool.kept() == 0);
    for (int i = 0; i < 8; ++i) pool.give(Image(i + 1, 1));
    CHECK(pool.kept() == 6);
    Image big = pool.take(8, 1);  // the two smallest were the ones let go
    CHECK(big.rgb.capacity() >= 24);
    pool.give(Image());  // no storage: nothing kept
    CHECK(pool.kept() == 5);
}
