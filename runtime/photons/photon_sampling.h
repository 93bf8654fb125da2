#pragma once
// Sampling helpers of the photon shooter: a frame about a normal, cosine-distributed
// directions, uniform points on triangles and parallelograms, mirror reflection and
// dielectric refraction with the exact Fresnel reflectance.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"

namespace kdpm {

inline constexpr float kPhotonPi = 3.14159265358979323846f;

// Two unit tangents completing the unit normal n to a right-handed frame (Duff et al. 2017).
KDPM_HD KDPM_INLINE void tangent_frame(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// Direction about the unit normal n with density cos(theta) / pi (Malley: a uniform disc lifted).
KDPM_HD KDPM_INLINE glm::vec3 cosine_direction(const glm::vec3& n, float u1, float u2) {
    const float r = sqrtf(u1);
    const float phi = 2.0f * kPhotonPi * u2;
    const float z = sqrtf(1.0f - u1 > 0.0f ? 1.0f - u1 : 0.0f);
    glm::vec3 t, b;
    tangent_frame(n, t, b);
    return glm::normalize(r * cosf(phi) * t + r * sinf(phi) * b + z * n);
}

// Uniform point on the triangle p0, p0 + e1, p0 + e2.
KDPM_HD KDPM_INLINE glm::vec3 triangle_point(const glm::vec3& p0, const glm::vec3& e1, const glm::vec3& e2, float u1,
                                             float u2) {
    const float s = sqrtf(u1);
    return p0 + (s * (1.0f - u2)) * e1 + (s * u2) * e2;
}

KDPM_HD KDPM_INLINE glm::vec3 reflect_about(const glm::vec3& d, const glm::vec3& n) { return d - 2.0f * glm::dot(d, n) * n; }

// Unpolarised Fresnel reflectance of a dielectric; cos_i > 0 on the incident side, eta = n_i / n_t.
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

// Refraction of the unit direction d through the unit normal n facing the incident side.
KDPM_HD KDPM_INLINE glm::vec3 refract_through(const glm::vec3& d, const glm::vec3& n, float eta, float cos_i, float cos_t) {
    return glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
}

}  // namespace kdpm
