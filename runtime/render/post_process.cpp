#include "runtime/render/post_process.h"

#include <algorithm>
#include <cmath>
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

float srgb_encode(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

namespace {

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
        const float v = linear.rgb[i];
        out.rgb[i] = std::isfinite(v) ? v * scale : 0.0f;
    }, 16384);
    if (s.bloom && out.width > 0 && out.height > 0) add_bloom(out, s);
    return out;
}

Image to_display(const Image& exposed, ToneMap tone_map) {
    Image out(exposed.width, exposed.height);
    cpu_parallel_for(exposed.rgb.size(), [&](std::uint64_t i) {
        out.rgb[i] = srgb_encode(tone_map_value(exposed.rgb[i], tone_map));
    }, 4096);
    return out;
}

}  // namespace kdpm
