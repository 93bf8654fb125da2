#include "runtime/view/frame_composer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "runtime/backend/cpu_parallel_for.h"


namespace kdpm {

namespace {

Image depth_view(const RenderResult& frame) {
    Image out(frame.linear.width, frame.linear.height);
    const auto& d = frame.aovs.depth;
    if (d.size() != out.pixel_count()) return out;
    float lo = std::numeric_limits<float>::infinity(), hi = 0.0f;
    for (float v : d)
        if (std::isfinite(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    const float span = hi > lo ? hi - lo : 1.0f;
    // Near is bright, far is dark, misses are black.
    for (std::size_t i = 0; i < d.size(); ++i) {
        const float g = std::isfinite(d[i]) ? 1.0f - 0.85f * (d[i] - lo) / span : 0.0f;
        for (int c = 0; c < 3; ++c) out.rgb[i * 3 + c] = g;
    }
    return out;
}

Image normal_view(const RenderResult& frame) {
    Image out(frame.linear.width, frame.linear.height);
    const auto& n = frame.aovs.normal;
    if (n.size() != out.pixel_count() * 3) return out;
    for (std::size_t i = 0; i < out.pixel_count(); ++i) {
        const bool hit = n[i * 3] != 0.0f || n[i * 3 + 1] != 0.0f || n[i * 3 + 2] != 0.0f;
        for (int c = 0; c < 3; ++c) out.rgb[i * 3 + c] = hit ? 0.5f + 0.5f * n[i * 3 + c] : 0.0f;
    }
    return out;
}

// Log-scaled heat map of the density between the frame's 1st and 99th percentiles.
Image density_view(const RenderResult& frame, const std::vector<float>& density) {
    Image out(frame.linear.width, frame.linear.height);
    if (density.size() != out.pixel_count()) return out;
    const DensityScale scale = density_scale(density);
    if (!scale.valid) return out;
    for (std::size_t i = 0; i < density.size(); ++i) {
        if (!(density[i] > 0.0f) || !std::isfinite(density[i])) continue;
        const glm::vec3 c = heat_color(density_scale_position(scale, std::log(density[i])));
        for (int k = 0; k < 3; ++k) out.rgb[i * 3 + k] = c[k];
    }
    return out;
}

}  // namespace

DensityScale density_scale(const std::vector<float>& density) {
    std::vector<float> logs;
    for (float d : density)
        if (d > 0.0f && std::isfinite(d)) logs.push_back(std::log(d));
    DensityScale scale;
    if (logs.empty()) return scale;
    std::sort(logs.begin(), logs.end());
    scale.log_lo = logs[logs.size() / 100];
    scale.log_hi = logs[logs.size() - 1 - logs.size() / 100];
    scale.valid = true;
    return scale;
}

float density_scale_position(const DensityScale& scale, float log_density) {
    const float span = scale.log_hi > scale.log_lo ? scale.log_hi - scale.log_lo : 1.0f;
    // 0.1 up: the lowest density shown is still visibly not black (a miss is).
    return 0.1f + 0.9f * (log_density - scale.log_lo) / span;
}

glm::vec3 heat_color(float t) {
    if (!std::isfinite(t)) t = 0.0f;
    t = std::clamp(t, 0.0f, 1.0f);
    const glm::vec3 stops[5] = {{0, 0, 0}, {0.1f, 0.1f, 0.9f}, {0.9f, 0.1f, 0.2f}, {1.0f, 0.85f, 0.1f}, {1, 1, 1}};
    const float x = t * 4.0f;
    const int i = std::min(3, static_cast<int>(x));
    return glm::mix(stops[i], stops[i + 1], x - static_cast<float>(i));
}

Image compose_view(const RenderResult& frame, const std::vector<float>& density, const ViewOptions& options) {
    // A frame rendered for another view lacks the depth or normal AOV until the one asked for
    // arrives: it is shown shaded meanwhile, not black.
    const std::size_t pixels = static_cast<std::size_t>(frame.linear.width) * frame.linear.height;
    switch (options.view) {
        case ViewKind::depth:
            if (frame.aovs.depth.size() == pixels) return depth_view(frame);
            break;
        case ViewKind::normal:
            if (frame.aovs.normal.size() == pixels * 3) return normal_view(frame);
            break;
        case ViewKind::photon_density: return density_view(frame, density);
        case ViewKind::shaded: break;
    }
    PostSettings post;
    post.exposure_stops = options.exposure_stops;
    post.tone_map = options.tone_map;
    // The renderer made this very image already when the frame was rendered with the view's
    // settings (the viewer asks for them); recomposed only when they changed since.
    const PostSettings& made = frame.post;
    if (!made.bloom && made.exposure_stops == post.exposure_stops && made.tone_map == post.tone_map &&
        frame.display.width == frame.linear.width && frame.display.height == frame.linear.height &&
        frame.display.rgb.size() == frame.linear.rgb.size())
        return frame.display;
    return to_display(expose(frame.linear, post), post.tone_map);
}

Image resize_nearest(Image source, int width, int height) {
    if (source.width == width && source.height == height) return source;
    Image out(width, height);
    if (source.width <= 0 || source.height <= 0) return out;
    for (int y = 0; y < height; ++y) {
        const int sy = std::min(source.height - 1, static_cast<int>(static_cast<long long>(y) * source.height / height));
        for (int x = 0; x < width; ++x) {
            const int sx = std::min(source.width - 1, static_cast<int>(static_cast<long long>(x) * source.width / width));
            const float* s = &source.rgb[(static_cast<std::size_t>(sy) * source.width + sx) * 3];
            float* d = &out.rgb[(static_cast<std::size_t>(y) * width + x) * 3];
            d[0] = s[0];
            d[1] = s[1];
            d[2] = s[2];
        }
    }
    return out;
}

void to_rgb8(const Image& image, std::vector<unsigned char>& out) {
    out.resize(image.rgb.size());
    cpu_parallel_for(image.rgb.size(), [&](std::uint64_t i) {
        const float v = std::isfinite(image.rgb[i]) ? std::clamp(image.rgb[i], 0.0f, 1.0f) : 0.0f;
        // lround(x) for x in [0, 255] without the libm call: a float's fraction x - trunc(x) is
        // exact, so the halfway case rounds up as lround's does.
        const float x = v * 255.0f;
        const int whole = static_cast<int>(x);
        out[i] = static_cast<unsigned char>(whole + (x - static_cast<float>(whole) >= 0.5f ? 1 : 0));
    }, 16384);
}

}  // namespace kdpm
