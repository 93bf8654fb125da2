#pragma once
// Möller–Trumbore ray/triangle intersection over the stored (v0, e1, e2) record. Written with
// negated comparisons so that NaN coordinates and zero-area triangles never report a hit.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"

namespace kdpm {

KDPM_HD KDPM_INLINE glm::vec3 to_vec3(const float (&a)[3]) { return glm::vec3(a[0], a[1], a[2]); }

// True when the ray hits the triangle at some t in (tmin, tmax); then t, u, v are set.
KDPM_HD KDPM_INLINE bool intersect_triangle(const TriangleRecord& tri, const glm::vec3& origin,
                                            const glm::vec3& direction, float tmin, float tmax, float& t,
                                            float& u, float& v) {
    const glm::vec3 e1 = to_vec3(tri.e1);
    const glm::vec3 e2 = to_vec3(tri.e2);
    const glm::vec3 p = glm::cross(direction, e2);
    const float det = glm::dot(e1, p);
    if (!(det != 0.0f)) return false;  // parallel, degenerate or NaN
    const float inv_det = 1.0f / det;
    const glm::vec3 s = origin - to_vec3(tri.v0);
    const float uu = glm::dot(s, p) * inv_det;
    if (!(uu >= 0.0f && uu <= 1.0f)) return false;
    const glm::vec3 q = glm::cross(s, e1);
    const float vv = glm::dot(direction, q) * inv_det;
    if (!(vv >= 0.0f && uu + vv <= 1.0f)) return false;
    const float tt = glm::dot(e2, q) * inv_det;
    if (!(tt > tmin && tt < tmax)) return false;
    t = tt;
    u = uu;
    v = vv;
    return true;
}

}  // namespace kdpm
