#pragma once
// Applying an affine map (formats/affine_map.h) to points, vectors and normals in kernels.
#include <glm/vec3.hpp>

#include "formats/affine_map.h"
#include "formats/host_device.h"

namespace kdpm {

KDPM_HD KDPM_INLINE glm::vec3 apply_point(const Affine& a, const glm::vec3& p) {
    return glm::vec3(a.m[0][0] * p.x + a.m[0][1] * p.y + a.m[0][2] * p.z + a.m[0][3],
                     a.m[1][0] * p.x + a.m[1][1] * p.y + a.m[1][2] * p.z + a.m[1][3],
                     a.m[2][0] * p.x + a.m[2][1] * p.y + a.m[2][2] * p.z + a.m[2][3]);
}

KDPM_HD KDPM_INLINE glm::vec3 apply_vector(const Affine& a, const glm::vec3& d) {
    return glm::vec3(a.m[0][0] * d.x + a.m[0][1] * d.y + a.m[0][2] * d.z,
                     a.m[1][0] * d.x + a.m[1][1] * d.y + a.m[1][2] * d.z,
                     a.m[2][0] * d.x + a.m[2][1] * d.y + a.m[2][2] * d.z);
}

// A normal of the object frame in the frame `inverse` maps from: the transpose of the inverse's
// linear part keeps it perpendicular to the mapped surface (not unit length).
KDPM_HD KDPM_INLINE glm::vec3 apply_normal(const Affine& inverse, const glm::vec3& n) {
    return glm::vec3(inverse.m[0][0] * n.x + inverse.m[1][0] * n.y + inverse.m[2][0] * n.z,
                     inverse.m[0][1] * n.x + inverse.m[1][1] * n.y + inverse.m[2][1] * n.z,
                     inverse.m[0][2] * n.x + inverse.m[1][2] * n.y + inverse.m[2][2] * n.z);
}

}  // namespace kdpm
