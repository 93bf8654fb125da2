#include "tools/bench/error_analysis.h"

#include <algorithm>
#include <cmath>

#include "runtime/render/image/post_process.h"

namespace kdpm::bench {
namespace {

float luminance(const Image& image, std::size_t pixel) {
    const float* c = &image.rgb[3 * pixel];
    return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
}

// True where pixels a and b see different surfaces (see edge_mask).
bool boundary(const AovImages& aovs, std::size_t a, std::size_t b) {
    const float da = aovs.depth[a], db = aovs.depth[b];
    const bool hit_a = std::isfinite(da), hit_b = std::isfinite(db);
    if (hit_a != hit_b) return true;
    if (!hit_a) return false;
    if (std::fabs(da - db) > 0.05f * std::min(da, db)) return true;
    const float* na = &aovs.normal[3 * a];
    const float* nb = &aovs.normal[3 * b];
    return na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2] < 0.866f;  // cos 30 degrees
}

}  // namespace

std::vector<std::uint8_t> edge_mask(const AovImages& aovs, int width, int height, int reach) {
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    std::vector<std::uint8_t> seed(pixels, 0), out(pixels, 0);
    if (aovs.depth.size() != pixels || aovs.normal.size() != 3 * pixels) return out;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * width + x;
            if ((x + 1 < width && boundary(aovs, p, p + 1)) || (y + 1 < height && boundary(aovs, p, p + width)))
                seed[p] = 1;
        }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            if (!seed[static_cast<std::size_t>(y) * width + x]) continue;
            for (int v = std::max(0, y - reach); v <= std::min(height - 1, y + reach + 1); ++v)
                for (int u = std::max(0, x - reach); u <= std::min(width - 1, x + reach + 1); ++u)
                    out[static_cast<std::size_t>(v) * width + u] = 1;
        }
    return out;
}

RegionSplit split_error(const Image& test, const Image& reference, const std::vector<std::uint8_t>& edges) {
    struct Sums {
        double error = 0, test = 0, reference = 0;
        std::size_t pixels = 0;
    } sums[2];
    const std::size_t pixels = reference.pixel_count();
    for (std::size_t p = 0; p < pixels; ++p) {
        Sums& s = sums[p < edges.size() && edges[p] ? 0 : 1];
        ++s.pixels;
        for (int c = 0; c < 3; ++c) {
            const double a = test.rgb[3 * p + c], b = reference.rgb[3 * p + c];
            s.error += (a - b) * (a - b) / (b * b + 0.01);
            s.test += a;
            s.reference += b;
        }
    }
    const double total_error = sums[0].error + sums[1].error;
    auto region = [&](const Sums& s) {
        RegionError r;
        if (s.pixels == 0) return r;
        r.relmse = s.error / (3.0 * static_cast<double>(s.pixels));
        r.mean_ratio = s.reference > 0 ? s.test / s.reference : 0.0;
        r.share = static_cast<double>(s.pixels) / static_cast<double>(pixels);
        r.error_share = total_error > 0 ? s.error / total_error : 0.0;
        return r;
    };
    return {region(sums[0]), region(sums[1])};
}

Image log_ratio_image(const Image& test, const Image& reference) {
    Image out(reference.width, reference.height);
    const std::size_t pixels = reference.pixel_count();
    double mean = 0;
    for (std::size_t p = 0; p < pixels; ++p) mean += luminance(reference, p);
    const float floor = static_cast<float>(0.01 * (pixels ? mean / static_cast<double>(pixels) : 0.0)) + 1e-12f;
    for (std::size_t p = 0; p < pixels; ++p) {
        const float stops = std::log2(std::max(luminance(test, p), floor) / std::max(luminance(reference, p), floor));
        const float v = std::clamp(std::fabs(stops), 0.0f, 1.0f);
        float* c = &out.rgb[3 * p];
        c[0] = stops > 0 ? v : 0.0f;
        c[1] = 0.0f;
        c[2] = stops < 0 ? v : 0.0f;
        // Small errors stay visible: a ramp lifted by a square root.
        for (int i = 0; i < 3; ++i) c[i] = std::sqrt(c[i]);
    }
    return out;
}

Image side_by_side(const Image& test, const Image& reference) {
    const int w = reference.width, h = reference.height;
    const PostSettings post;  // the same exposure and tone map for both
    const Image a = to_display(expose(test, post), post.tone_map);
    const Image b = to_display(expose(reference, post), post.tone_map);
    const Image e = log_ratio_image(test, reference);
    Image out(3 * w, h);
    const Image* parts[3] = {&a, &b, &e};
    for (int y = 0; y < h; ++y)
        for (int i = 0; i < 3; ++i)
            std::copy_n(&parts[i]->rgb[3 * static_cast<std::size_t>(y) * w], 3 * static_cast<std::size_t>(w),
                        &out.rgb[3 * (static_cast<std::size_t>(y) * 3 * w + static_cast<std::size_t>(i) * w)]);
    return out;
}

}  // namespace kdpm::bench
