#pragma once
// The specular BSDFs: perfect mirror reflection and a smooth dielectric (exact unpolarised
// Fresnel reflectance, Snell refraction).
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/triangle_intersect.h"

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

KDPM_HD KDPM_INLINE float glass_ior(const MaterialRecord& m) { return m.ior > 0.0f ? m.ior : kDefaultGlassIor; }

KDPM_HD KDPM_INLINE bool is_specular(const MaterialRecord& m) {
    return m.kind == static_cast<std::uint32_t>(MaterialKind::mirror) ||
           m.kind == static_cast<std::uint32_t>(MaterialKind::glass);
}

// The Fresnel reflectance of glass material m for direction d at unit normal n facing the incident
// side (front: d arrived from outside); unless it is 1, refracted receives the transmitted direction.
KDPM_HD KDPM_INLINE float glass_fresnel(const MaterialRecord& m, const glm::vec3& d, const glm::vec3& n, bool front,
                                        glm::vec3& refracted) {
    const float ior = glass_ior(m);
    return fresnel_refract(d, n, front ? 1.0f / ior : ior, refracted);
}

// One branch of a specular bounce: the new direction, the throughput factor, and whether the ray
// went through the surface (its origin then lies below it).
struct SpecularScatter {
    glm::vec3 direction;
    glm::vec3 weight;
    bool transmitted;
};

// Mirror or glass material m (is_specular): the mirror reflects; glass reflects when choose(),
// a uniform number in [0, 1), falls below the Fresnel reflectance and refracts otherwise, so the
// Fresnel weights cancel. choose is called for glass only.
template <class Choose>
KDPM_HD KDPM_INLINE SpecularScatter scatter_specular(const MaterialRecord& m, const glm::vec3& d, const glm::vec3& n,
                                                     bool front, Choose&& choose) {
    if (m.kind == static_cast<std::uint32_t>(MaterialKind::mirror))
        return SpecularScatter{reflect_dir(d, n), to_vec3(m.specular), false};
    glm::vec3 refracted(0.0f);
    const float f = glass_fresnel(m, d, n, front, refracted);
    if (choose() < f) return SpecularScatter{reflect_dir(d, n), glm::vec3(1.0f), false};
    return SpecularScatter{refracted, to_vec3(m.transmission), true};
}

}  // namespace kdpm
