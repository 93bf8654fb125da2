#pragma once
// Colours are glm::vec3 (linear RGB); to_vec3 (runtime/geometry/triangle_intersect.h) reads one
// from a record's float[3]. Here: the helpers the transport kernels share.
#include <glm/vec3.hpp>

#include "formats/host_device.h"

namespace kdpm {

KDPM_HD KDPM_INLINE float max_component(const glm::vec3& v) {
    return v.x > v.y ? (v.x > v.z ? v.x : v.z) : (v.y > v.z ? v.y : v.z);
}

// Russian roulette on a reflectance: survive with probability max channel (at most 1), then
// rescale the weight so its expectation is weight * reflectance. False when the path ends.
KDPM_HD KDPM_INLINE bool russian_roulette(glm::vec3& weight, const glm::vec3& reflectance, float u) {
    float q = max_component(reflectance);
    q = q > 1.0f ? 1.0f : q;
    if (!(q > 0.0f) || u >= q) return false;
    weight *= reflectance / q;
    return true;
}

}  // namespace kdpm
