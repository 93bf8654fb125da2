#pragma once
// One record of the irradiance cache (Ward, Rubinstein & Clear 1988) with its gradients (Ward &
// Heckbert 1992): the indirect irradiance gathered at a point, valid around it as far as the
// error bound allows, and extrapolated to nearby points and normals to first order.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"

namespace kdpm {

struct IrradianceRecord {
    glm::vec3 position;
    float radius = 0.0f;          // R_i: the nearest gather hit's distance, clamped (irradiance_record_pass.h)
    glm::vec3 normal;             // unit geometric normal, the gather rays' axis
    glm::vec3 irradiance;         // E_i, per channel
    glm::vec3 rotation[3];        // dE_c / d(rotation axis) for channel c: E(n) ~ E_i + (n_i x n) . rotation[c]
    glm::vec3 translation[3];     // dE_c / dx for channel c: E(p) ~ E_i + (p - p_i) . translation[c]
};

// Ward's error measure e_i(p, n) = |p - p_i| / R_i + sqrt(1 - n . n_i); the weight is 1 / e_i
// and the record is used where e_i < accuracy (weight > 1 / a). Negative: never usable there.
KDPM_HD KDPM_INLINE float record_error(const IrradianceRecord& r, const glm::vec3& p, const glm::vec3& n) {
    const float c = glm::dot(n, r.normal);
    if (!(c > 0.0f)) return -1.0f;
    const glm::vec3 d = p - r.position;
    // Ward's "in front" test: a record standing in front of p (p behind its surface) sees a
    // different hemisphere: a step's top must not light the floor at its foot. Measured along
    // the mean normal, p - p_i is level on a sphere, so the tolerance only absorbs facets.
    if (glm::dot(d, n + r.normal) * 0.5f < -0.01f * r.radius) return -1.0f;
    const float s = 1.0f - c;
    return glm::length(d) / r.radius + sqrtf(s > 0.0f ? s : 0.0f);
}

// The record's irradiance carried to (p, n) by its gradients, never negative.
KDPM_HD KDPM_INLINE glm::vec3 extrapolated_irradiance(const IrradianceRecord& r, const glm::vec3& p,
                                                      const glm::vec3& n) {
    const glm::vec3 d = p - r.position;
    const glm::vec3 axis = glm::cross(r.normal, n);
    glm::vec3 e;
    for (int c = 0; c < 3; ++c) {
        const float v = r.irradiance[c] + glm::dot(axis, r.rotation[c]) + glm::dot(d, r.translation[c]);
        e[c] = v > 0.0f ? v : 0.0f;
    }
    return e;
}

}  // namespace kdpm
