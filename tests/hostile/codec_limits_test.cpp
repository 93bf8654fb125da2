// The RGBE photon power codec at the top of the float range: saturate, never wrap to black.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "formats/photon_layout.h"

using namespace kdpm;

TEST_CASE("encode_rgbe saturates at 2^127 and above instead of wrapping to black", "[hostile][codec]") {
    const float big[] = {std::ldexp(1.0f, 127), std::ldexp(1.5f, 127), std::numeric_limits<float>::max(),
                         std::numeric_limits<float>::infinity()};
    for (float p : big) {
        INFO(p);
        float d[3];
        decode_rgbe(encode_rgbe(p, 0.0f, p), d);
        CHECK(d[0] > 1e38f);
        CHECK(d[1] == 0.0f);
        CHECK(d[2] > 1e38f);
    }
    // Just below the limit the codec is exact to its usual precision.
    float d[3];
    const float below = std::ldexp(1.0f, 126);
    decode_rgbe(encode_rgbe(below, below, below), d);
    CHECK(d[0] == Approx(below).epsilon(1.0 / 256));
}
