#pragma once
// Sampling the area lights: choosing one by power (binary search in the cumulative table that
// light_power_table builds on the host) and a uniform point on it. Photon emission and direct
// lighting both sample lights through these.
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/triangle_intersect.h"

namespace kdpm {

// The lights as a discrete distribution by emitted power, in host or device memory.
struct LightSelection {
    const float* cdf = nullptr;  // cdf[i] = (power[0] + ... + power[i]) / total; cdf[count-1] = 1
    std::uint32_t count = 0;     // 0 (and cdf nullptr) when no light emits
    float total_power = 0.0f;    // sum of AreaLightRecord::power over the lights that emit
};

// Index i with cdf[i-1] <= u < cdf[i], for u in [0, 1); count must be > 0.
KDPM_HD KDPM_INLINE std::uint32_t pick_light(const LightSelection& s, float u) {
    std::uint32_t lo = 0, hi = s.count - 1;
    while (lo < hi) {
        const std::uint32_t mid = (lo + hi) / 2;
        if (u < s.cdf[mid]) hi = mid;
        else lo = mid + 1;
    }
    return lo;
}

// The probability that pick_light returns light i.
KDPM_HD KDPM_INLINE float pick_probability(const LightSelection& s, std::uint32_t i) {
    return s.cdf[i] - (i > 0 ? s.cdf[i - 1] : 0.0f);
}

// The side the light emits to: along cross(e1, e2), unit length.
KDPM_HD KDPM_INLINE glm::vec3 light_normal(const AreaLightRecord& l) {
    return glm::normalize(glm::cross(to_vec3(l.e1), to_vec3(l.e2)));
}

// A point on the light for the unit square sample (a, b), uniform over its area (triangles by
// the square-root warp).
KDPM_HD KDPM_INLINE glm::vec3 point_on_light(const AreaLightRecord& l, float a, float b) {
    const glm::vec3 p0 = to_vec3(l.p0), e1 = to_vec3(l.e1), e2 = to_vec3(l.e2);
    if (l.shape == static_cast<std::uint32_t>(LightShape::triangle)) {
        const float s = sqrtf(a);
        return p0 + (s * (1.0f - b)) * e1 + (s * b) * e2;
    }
    return p0 + a * e1 + b * e2;
}

}  // namespace kdpm
