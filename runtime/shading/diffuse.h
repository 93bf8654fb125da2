#pragma once
// The Lambertian BSDF: its value albedo / pi and cosine-distributed sampling about a normal.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/shading/constants.h"

namespace kdpm {

// f_r of a Lambertian surface.
KDPM_HD KDPM_INLINE glm::vec3 lambert_brdf(const glm::vec3& albedo) { return albedo * kInvPi; }

// Two unit tangents completing the unit normal n to a right-handed frame (Duff et al. 2017).
KDPM_HD KDPM_INLINE void tangent_frame(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// Indirect light travels by the geometric normal in every mode: the photon shooter bounces about
// it and a photon map's density is flux per geometric area, so the path tracer and the gather
// rays sample about it too and all modes solve the same equation; shading normals shade direct
// light and estimates. (Bouncing about a tilted shading normal and ending the rays it sends into
// the surface leaves SPPM brighter than the reference path tracer.)
// Direction about the unit normal n with density cos(theta) / pi (Malley: a uniform disc lifted).
KDPM_HD KDPM_INLINE glm::vec3 cosine_direction(const glm::vec3& n, float u1, float u2) {
    const float r = sqrtf(u1);
    const float phi = 2.0f * kPi * u2;
    const float z = sqrtf(1.0f - u1 > 0.0f ? 1.0f - u1 : 0.0f);
    glm::vec3 t, b;
    tangent_frame(n, t, b);
    return glm::normalize(r * cosf(phi) * t + r * sinf(phi) * b + z * n);
}

}  // namespace kdpm
