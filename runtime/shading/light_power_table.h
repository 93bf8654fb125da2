#pragma once
// Host side of light selection: the cumulative power of the scene's lights, built once per
// scene (used in place on the CPU, or uploaded once for CUDA).
#include <vector>

#include "runtime/geometry/geometry_view.h"
#include "runtime/shading/area_light.h"

namespace kdpm {

struct LightPowerTable {
    std::vector<float> cdf;    // empty when no light has positive, finite power
    float total_power = 0.0f;  // 0 then

    // Over this table's storage, which must outlive it.
    LightSelection selection() const {
        return LightSelection{cdf.empty() ? nullptr : cdf.data(), static_cast<std::uint32_t>(cdf.size()), total_power};
    }
};

// cdf[i] = (power[0] + ... + power[i]) / total, summed in double, the last entry exactly 1;
// lights with non-finite or non-positive power get probability 0.
LightPowerTable light_power_table(const GeometryView& geometry);

}  // namespace kdpm
