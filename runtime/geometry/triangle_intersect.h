#pragma once
// One ray against one stored triangle (moller_trumbore.h's scalar test), and the record's floats
// as GLM vectors.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/moller_trumbore.h"

namespace kdpm {

KDPM_HD KDPM_INLINE glm::vec3 to_vec3(const float (&a)[3]) { return glm::vec3(a[0], a[1], a[2]); }

// True when the ray hits the triangle at some t in (tmin, tmax); then t, u, v are set.
KDPM_HD KDPM_INLINE bool intersect_triangle(const TriangleRecord& tri, const glm::vec3& origin,
                                            const glm::vec3& direction, float tmin, float tmax, float& t,
                                            float& u, float& v) {
    const float o[3] = {origin.x, origin.y, origin.z}, d[3] = {direction.x, direction.y, direction.z};
    const TriangleTest<ScalarOps> r = moller_trumbore<ScalarOps, true>(tri.v0, tri.e1, tri.e2, o, d, tmin, tmax, true);
    if (!r.hit) return false;
    t = r.t;
    u = r.u;
    v = r.v;
    return true;
}

}  // namespace kdpm
