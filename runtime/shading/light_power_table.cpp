#include "runtime/shading/light_power_table.h"

#include <cmath>

namespace kdpm {

LightPowerTable light_power_table(const GeometryView& g) {
    std::vector<double> sums(g.light_count);
    double total = 0.0;
    for (std::uint32_t i = 0; i < g.light_count; ++i) {
        const float p = g.lights[i].power;
        if (std::isfinite(p) && p > 0.0f) total += p;
        sums[i] = total;
    }
    LightPowerTable table;
    if (!(total > 0.0)) return table;
    table.total_power = static_cast<float>(total);
    table.cdf.resize(g.light_count);
    for (std::uint32_t i = 0; i < g.light_count; ++i) table.cdf[i] = static_cast<float>(sums[i] / total);
    table.cdf.back() = 1.0f;
    return table;
}

}  // namespace kdpm
