#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "formats/photon_layout.h"

using namespace kdpm;

TEST_CASE("RGBE power round-trips within 1/128 of the largest channel", "[photons][codec]") {
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int i = 0; i < 10000; ++i) {
        float scale = std::pow(10.0f, -8.0f + 12.0f * u(rng));
        float c[3] = {u(rng) * scale, u(rng) * scale, u(rng) * scale}, d[3];
        decode_rgbe(encode_rgbe(c[0], c[1], c[2]), d);
        float m = std::max(c[0], std::max(c[1], c[2]));
        for (int a = 0; a < 3; ++a) REQUIRE(std::fabs(d[a] - c[a]) <= m / 128.0f);
    }
    float d[3];
    decode_rgbe(encode_rgbe(0.0f, 0.0f, 0.0f), d);
    CHECK((d[0] == 0.0f && d[1] == 0.0f && d[2] == 0.0f));
}

TEST_CASE("Octahedral directions round-trip to within 0.05 degrees", "[photons][codec]") {
    std::mt19937 rng(2);
    std::normal_distribution<float> g;
    for (int i = 0; i < 10000; ++i) {
        float v[3] = {g(rng), g(rng), g(rng)}, d[3];
        float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (float& c : v) c /= len;
        if (i < 6) {  // the axes too
            for (float& c : v) c = 0.0f;
            v[i / 2] = i % 2 ? -1.0f : 1.0f;
        }
        decode_octahedral(encode_octahedral(v[0], v[1], v[2]), d);
        REQUIRE(double(v[0]) * d[0] + double(v[1]) * d[1] + double(v[2]) * d[2] > std::cos(0.05 * 3.14159265 / 180.0));
    }
}

TEST_CASE("Photon flags carry the bounce and the caustic bit", "[photons][codec]") {
    std::uint32_t f = make_photon_flags(3, true);
    CHECK(photon_bounce(f) == 3);
    CHECK((f & kPhotonCaustic) != 0);
    CHECK(photon_bounce(make_photon_flags(0, false)) == 0);
}
