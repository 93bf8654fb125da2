#include "builders/geometry/import/texture_mips.h"

#include <algorithm>
#include <cmath>

namespace kdpm {

namespace {

struct Tap {
    std::uint32_t index;
    double weight;
};

// For each coarse texel along one axis, the fine texels it covers and their shares: coarse
// texel i spans fine coordinates [i * fine / coarse, (i + 1) * fine / coarse).
std::vector<std::vector<Tap>> box_taps(std::uint32_t fine, std::uint32_t coarse) {
    std::vector<std::vector<Tap>> taps(coarse);
    const double scale = static_cast<double>(fine) / coarse;
    for (std::uint32_t i = 0; i < coarse; ++i) {
        const double a = i * scale, b = (i + 1) * scale;
        for (auto j = static_cast<std::uint32_t>(std::floor(a)); j < fine && j < b; ++j) {
            const double overlap = std::min(b, j + 1.0) - std::max(a, static_cast<double>(j));
            if (overlap > 0.0) taps[i].push_back({j, overlap / scale});
        }
    }
    return taps;
}

}  // namespace

std::vector<Texel> downsample_box(const std::vector<Texel>& level, std::uint32_t width, std::uint32_t height) {
    const std::uint32_t w = texture_level_side(width, 1), h = texture_level_side(height, 1);
    const auto tx = box_taps(width, w), ty = box_taps(height, h);
    std::vector<Texel> out(std::size_t{w} * h);
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x) {
            double sum[3] = {0, 0, 0};
            for (const Tap& row : ty[y])
                for (const Tap& col : tx[x]) {
                    const Texel& t = level[std::size_t{row.index} * width + col.index];
                    for (int c = 0; c < 3; ++c) sum[c] += row.weight * col.weight * t.rgb[c];
                }
            for (int c = 0; c < 3; ++c) out[std::size_t{y} * w + x].rgb[c] = static_cast<float>(sum[c]);
        }
    return out;
}

std::vector<Texel> build_mip_chain(std::vector<Texel> level0, std::uint32_t width, std::uint32_t height) {
    std::vector<Texel> chain = level0;
    std::vector<Texel> level = std::move(level0);
    for (std::uint32_t l = 1; l < texture_level_count(width, height); ++l) {
        level = downsample_box(level, texture_level_side(width, l - 1), texture_level_side(height, l - 1));
        chain.insert(chain.end(), level.begin(), level.end());
    }
    return chain;
}

}  // namespace kdpm
