#pragma once
// Perfect mirror reflection and smooth dielectric refraction with the exact Fresnel term.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"

namespace kdpm {

// d: incoming direction (unit, towards the surface); n: unit normal facing against d.
KDPM_HD KDPM_INLINE glm::vec3 reflect_dir(const glm::vec3& d, const glm::vec3& n) {
    return d - 2.0f * glm::dot(d, n) * n;
}

// Fresnel reflectance of unpolarised light at a dielectric boundary; cos_i > 0 is the cosine on
// the incident side, eta = n_incident / n_transmitted. Returns 1 on total internal reflection,
// else sets the refracted direction.
KDPM_HD KDPM_INLINE float fresnel_refract(const glm::vec3& d, const glm::vec3& n, float eta, glm::vec3& refracted) {
    const float cos_i = -glm::dot(d, n);
    const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) return 1.0f;
    const float cos_t = glm::sqrt(1.0f - sin2_t);
    refracted = glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
    const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (rs * rs + rp * rp);
}

}  // namespace kdpm
