#include "runtime/render/image/post_process.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

#include "runtime/backend/cpu_parallel_for.h"

namespace kdpm {

ToneMap parse_tone_map(std::string_view text) {
    if (text == "none") return ToneMap::none;
    if (text == "reinhard") return ToneMap::reinhard;
    if (text == "aces") return ToneMap::aces;
    throw std::invalid_argument("expected reinhard, aces or none, got '" + std::string(text) + "'");
}

float tone_map_value(float v, ToneMap tone_map) {
    v = std::max(v, 0.0f);
    switch (tone_map) {
        case ToneMap::reinhard: return v / (1.0f + v);
        case ToneMap::aces: {
            // Krzysztof Narkowicz's fit of the ACES filmic curve.
            const float a = 2.51f, b = 0.03f, c = 2.43f, d = 0.59f, e = 0.14f;
            return std::clamp((v * (a * v + b)) / (v * (c * v + d) + e), 0.0f, 1.0f);
        }
        case ToneMap::none: break;
    }
    return std::min(v, 1.0f);
}

namespace {

// 2^(5e/12) for the exponents e = -9..0 of the values the power curve sees (x > 0.0031308),
// each the float nearest to it.
constexpr float kFifthTwelfthOfPowersOfTwo[10] = {
    0.07432544231414795f, 0.09921256452798843f, 0.13243289291858673f, 0.1767766922712326f, 0.23596857488155365f,
    0.31498026847839355f, 0.4204482138156891f,  0.5612310171127319f,  0.7491535544395447f, 1.0f};

// x^(1/2.4) = x^(5/12) for x in (0.0031308, 1]: x = m 2^e with m in [1, 2), m^(5/12) from a
// degree-6 polynomial in m - 1 (a Chebyshev fit, relative error under 3e-7, a fiftieth of a
// 16-bit step), 2^(5e/12) from the table. Unlike std::pow, this is inline and free of libm
// calls, so the loop below overlaps pixels and the display conversion stays cheap.
inline float fifth_twelfth_power(float x) {
    std::uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const int e = static_cast<int>(bits >> 23) - 127;
    const std::uint32_t mantissa_bits = (bits & 0x007fffffu) | 0x3f800000u;
    float m;
    std::memcpy(&m, &mantissa_bits, sizeof m);
    const float u = m - 1.0f;
    const float p = 1.000000238418579f +
                    u * (0.4166446328163147f +
                         u * (-0.121149942278862f +
                              u * (0.0616292729973793f +
                                   u * (-0.033010903745889664f +
                                        u * (0.013470930978655815f + u * -0.0027445252053439617f)))));
    return p * kFifthTwelfthOfPowersOfTwo[std::clamp(e, -9, 0) + 9];
}

inline float srgb_of_unit(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * fifth_twelfth_power(x) - 0.055f;
}

}  // namespace

float srgb_encode(float x) { return srgb_of_unit(x); }

namespace {

// A linear value scaled by the exposure; a NaN or infinite one (a broken sample) shows black.
inline float exposed_value(float v, float scale) { return std::isfinite(v) ? v * scale : 0.0f; }

// Separable Gaussian blur of one direction (dx, dy) over an RGB image, clamped at the edges.
Image blur(const Image& in, const std::vector<float>& weights, int dx, int dy) {
    Image out(in.width, in.height);
    const int radius = static_cast<int>(weights.size()) - 1;
    cpu_parallel_for(in.pixel_count(), [&](std::uint64_t i) {
        const int x = static_cast<int>(i % in.width), y = static_cast<int>(i / in.width);
        float acc[3] = {0, 0, 0};
        for (int k = -radius; k <= radius; ++k) {
            const int sx = std::clamp(x + k * dx, 0, in.width - 1);
            const int sy = std::clamp(y + k * dy, 0, in.height - 1);
            const float w = weights[static_cast<std::size_t>(std::abs(k))];
            const std::size_t j = (static_cast<std::size_t>(sy) * in.width + sx) * 3;
            for (int c = 0; c < 3; ++c) acc[c] += w * in.rgb[j + c];
        }
        for (int c = 0; c < 3; ++c) out.rgb[i * 3 + c] = acc[c];
    });
    return out;
}

void add_bloom(Image& img, const PostSettings& s) {
    Image bright(img.width, img.height);
    for (std::size_t i = 0; i < img.rgb.size(); ++i) bright.rgb[i] = std::max(img.rgb[i] - s.bloom_threshold, 0.0f);
    const float sigma = std::max(1.0f, s.bloom_radius * static_cast<float>(img.height));
    const int radius = static_cast<int>(std::ceil(3.0f * sigma));
    std::vector<float> w(static_cast<std::size_t>(radius) + 1);
    float sum = 0;
    for (int k = 0; k <= radius; ++k) {
        w[static_cast<std::size_t>(k)] = std::exp(-0.5f * k * k / (sigma * sigma));
        sum += (k == 0 ? 1.0f : 2.0f) * w[static_cast<std::size_t>(k)];
    }
    for (float& v : w) v /= sum;
    Image glow = blur(blur(bright, w, 1, 0), w, 0, 1);
    for (std::size_t i = 0; i < img.rgb.size(); ++i) img.rgb[i] += s.bloom_strength * glow.rgb[i];
}

}  // namespace

Image expose(const Image& linear, const PostSettings& s) {
    Image out(linear.width, linear.height);
    out.rgb.resize(linear.rgb.size());
    const float scale = std::exp2(s.exposure_stops);
    cpu_parallel_for(linear.rgb.size(), [&](std::uint64_t i) {
        out.rgb[i] = exposed_value(linear.rgb[i], scale);
    }, 16384);
    if (s.bloom && out.width > 0 && out.height > 0) add_bloom(out, s);
    return out;
}

namespace {

// Calls body(curve) with the tone curve as a lambda of its own: the choice made once, outside
// the per-value loops.
template <class Body>
void with_tone_curve(ToneMap tone_map, const Body& body) {
    switch (tone_map) {
        case ToneMap::reinhard: body([](float v) { return tone_map_value(v, ToneMap::reinhard); }); break;
        case ToneMap::aces: body([](float v) { return tone_map_value(v, ToneMap::aces); }); break;
        case ToneMap::none: body([](float v) { return tone_map_value(v, ToneMap::none); }); break;
    }
}

}  // namespace

Image to_display(const Image& exposed, ToneMap tone_map) {
    Image out(exposed.width, exposed.height);
    with_tone_curve(tone_map, [&](auto curve) {
        const float* in = exposed.rgb.data();
        float* to = out.rgb.data();
        cpu_parallel_for(exposed.rgb.size(), [=](std::uint64_t i) { to[i] = srgb_of_unit(curve(in[i])); }, 4096);
    });
    return out;
}

void post_process(const Image& linear, const PostSettings& s, Image& exposed, Image& display) {
    if (s.bloom) {
        exposed = expose(linear, s);
        display = to_display(exposed, s.tone_map);
        return;
    }
    exposed.reshape(linear.width, linear.height);
    display.reshape(linear.width, linear.height);
    const float scale = std::exp2(s.exposure_stops);
    with_tone_curve(s.tone_map, [&](auto curve) {
        const float* in = linear.rgb.data();
        float* to_exposed = exposed.rgb.data();
        float* to_display = display.rgb.data();
        cpu_parallel_for(linear.rgb.size(), [=](std::uint64_t i) {
            const float v = exposed_value(in[i], scale);
            to_exposed[i] = v;
            to_display[i] = srgb_of_unit(curve(v));
        }, 4096);
    });
}

}  // namespace kdpm
