#pragma once
// The area lights as the emission kernel samples them: a light is chosen with probability
// proportional to its power (binary search in a cumulative table built on the host).
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"

namespace kdpm {

struct LightTable {
    const AreaLightRecord* lights = nullptr;
    const float* cdf = nullptr;  // cdf[i] = sum of power over lights 0..i / total; cdf[count-1] = 1
    std::uint32_t count = 0;
    float total_power = 0.0f;    // sum of AreaLightRecord::power (the sampling weights)
};

// The light whose cdf interval holds u in [0, 1).
KDPM_HD KDPM_INLINE std::uint32_t pick_light(const LightTable& t, float u) {
    std::uint32_t lo = 0, hi = t.count - 1;
    while (lo < hi) {
        std::uint32_t mid = (lo + hi) / 2;
        if (u < t.cdf[mid]) hi = mid;
        else lo = mid + 1;
    }
    return lo;
}

}  // namespace kdpm
