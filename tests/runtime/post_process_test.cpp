// Exposure, tone curves and the sRGB transfer function against their definitions.
#include <catch2/catch.hpp>

#include <cmath>

#include "runtime/render/post_process.h"

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
