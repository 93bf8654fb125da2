#pragma once
// Normals at a hit: the geometric normal of the triangle and the interpolated shading normal
// (per-vertex normals when the file has them, else the geometric normal).
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/triangle_intersect.h"

namespace kdpm {

// Unit normal along cross(e1, e2): counter-clockwise winding faces the viewer.
KDPM_HD KDPM_INLINE glm::vec3 geometric_normal(const TriangleRecord& tri) {
    return glm::normalize(glm::cross(to_vec3(tri.e1), to_vec3(tri.e2)));
}

// The point at barycentrics (u, v).
KDPM_HD KDPM_INLINE glm::vec3 surface_point(const TriangleRecord& tri, float u, float v) {
    return to_vec3(tri.v0) + u * to_vec3(tri.e1) + v * to_vec3(tri.e2);
}

// Interpolated unit shading normal at barycentrics (u, v) of triangle `index`; falls back to
// the geometric normal when the triangle has none or they interpolate to zero.
KDPM_HD KDPM_INLINE glm::vec3 shading_normal(const GeometryView& g, std::uint32_t index, float u, float v) {
    const TriangleRecord& tri = g.triangles[index];
    if (g.normals != nullptr && (tri.flags & 1u) != 0u) {
        const TriangleNormals& n = g.normals[index];
        const glm::vec3 s = (1.0f - u - v) * to_vec3(n.n[0]) + u * to_vec3(n.n[1]) + v * to_vec3(n.n[2]);
        const float len2 = glm::dot(s, s);
        if (len2 > 0.0f) return s / glm::sqrt(len2);
    }
    return geometric_normal(tri);
}

}  // namespace kdpm
