#pragma once
// A surface interaction in the form every pass uses, and the material at a hit.
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/ray.h"
#include "runtime/geometry/surface_normal.h"

namespace kdpm {

struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 shading_normal;    // facing the incoming ray
    glm::vec3 geometric_normal;  // facing the incoming ray
    bool front;                  // the ray hit the side cross(e1, e2) points to
};

// The hit of `ray`, at its ray parameter.
KDPM_HD KDPM_INLINE SurfacePoint surface_at(const GeometryView& g, const Ray& ray, const Hit& hit) {
    const TriangleRecord& tri = g.triangles[hit.triangle];
    const glm::vec3 ng = geometric_normal(tri);
    glm::vec3 ns = shading_normal(g, hit.triangle, hit.u, hit.v);
    SurfacePoint s;
    s.front = glm::dot(ng, ray.direction) < 0.0f;
    s.geometric_normal = s.front ? ng : -ng;
    if (glm::dot(ns, s.geometric_normal) < 0.0f) ns = -ns;
    s.shading_normal = ns;
    s.position = ray.origin + hit.t * ray.direction;
    return s;
}

// The triangle's material; mid grey for an index past the table (a hand-built scene without
// materials; a loaded file's indices are all checked).
KDPM_HD KDPM_INLINE MaterialRecord material_of(const GeometryView& g, std::uint32_t triangle) {
    const std::uint32_t m = g.triangles[triangle].material;
    if (m < g.material_count) return g.materials[m];
    MaterialRecord grey{};
    grey.diffuse[0] = grey.diffuse[1] = grey.diffuse[2] = 0.5f;
    return grey;
}

}  // namespace kdpm
