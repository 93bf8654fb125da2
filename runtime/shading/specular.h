#pragma once
// The specular BSDFs: perfect mirror reflection and a smooth dielectric (exact unpolarised
// Fresnel reflectance, Snell refraction).
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"

namespace kdpm {

// d: incoming direction (towards the surface); n: unit normal facing against d.
KDPM_HD KDPM_INLINE glm::vec3 reflect_dir(const glm::vec3& d, const glm::vec3& n) { return d - 2.0f * glm::dot(d, n) * n; }

// Fresnel reflectance of a dielectric; cos_i > 0 on the incident side, eta = n_i / n_t.
// Returns 1 for total internal reflection; cos_t receives the transmitted cosine otherwise.
KDPM_HD KDPM_INLINE float dielectric_fresnel(float cos_i, float eta, float& cos_t) {
    const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) {
        cos_t = 0.0f;
        return 1.0f;
    }
    cos_t = sqrtf(1.0f - sin2_t);
    const float rs = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    const float rp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    return 0.5f * (rs * rs + rp * rp);
}

// The unit direction d refracted through the unit normal n facing the incident side, with the
// cosines dielectric_fresnel gave.
KDPM_HD KDPM_INLINE glm::vec3 refract_dir(const glm::vec3& d, const glm::vec3& n, float eta, float cos_i, float cos_t) {
    return glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
}

// Both at once: the Fresnel reflectance, and unless it is 1 (total internal reflection) the
// refracted direction.
KDPM_HD KDPM_INLINE float fresnel_refract(const glm::vec3& d, const glm::vec3& n, float eta, glm::vec3& refracted) {
    const float cos_i = -glm::dot(d, n);
    float cos_t;
    const float f = dielectric_fresnel(cos_i, eta, cos_t);
    if (cos_t > 0.0f) refracted = refract_dir(d, n, eta, cos_i, cos_t);  // not totally reflected
    return f;
}

}  // namespace kdpm
