#include "runtime/render/light_distribution.h"

#include <cmath>

namespace kdpm {

std::vector<float> light_power_cdf(const GeometryView& g) {
    std::vector<double> sums(g.light_count);
    double total = 0.0;
    for (std::uint32_t i = 0; i < g.light_count; ++i) {
        const float p = g.lights[i].power;
        if (std::isfinite(p) && p > 0.0f) total += p;
        sums[i] = total;
    }
    if (!(total > 0.0)) return {};
    std::vector<float> cdf(g.light_count);
    for (std::uint32_t i = 0; i < g.light_count; ++i) cdf[i] = static_cast<float>(sums[i] / total);
    cdf.back() = 1.0f;
    return cdf;
}

}  // namespace kdpm
