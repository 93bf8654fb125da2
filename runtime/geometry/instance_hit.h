#pragma once
// What a hit names, in world space: its object's view (for materials, uvs, textures) and its
// triangle placed by the instance's map. A scene without instances gets its own records back.
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/affine.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/ray.h"
#include "runtime/geometry/surface_normal.h"

namespace kdpm {

// The view whose triangle, material and uv tables hit.triangle indexes.
KDPM_HD KDPM_INLINE const GeometryView& object_of(const GeometryView& g, const Hit& hit) {
    return hit.instance == kNoInstance ? g : g.objects[g.instances[hit.instance].object];
}

// The hit triangle in world space. An instance's triangle keeps its barycentrics under the map.
KDPM_HD KDPM_INLINE TriangleRecord world_triangle(const GeometryView& g, const Hit& hit) {
    if (hit.instance == kNoInstance) return g.triangles[hit.triangle];
    const InstancePlacement& p = g.instances[hit.instance];
    TriangleRecord t = g.objects[p.object].triangles[hit.triangle];
    const glm::vec3 v0 = apply_point(p.world_from_object, to_vec3(t.v0));
    const glm::vec3 e1 = apply_vector(p.world_from_object, to_vec3(t.e1));
    const glm::vec3 e2 = apply_vector(p.world_from_object, to_vec3(t.e2));
    for (int a = 0; a < 3; ++a) t.v0[a] = v0[a], t.e1[a] = e1[a], t.e2[a] = e2[a];
    return t;
}

// The unit shading normal at the hit in world space (shading_normal of its object, mapped).
KDPM_HD KDPM_INLINE glm::vec3 world_shading_normal(const GeometryView& g, const Hit& hit) {
    if (hit.instance == kNoInstance) return shading_normal(g, hit.triangle, hit.u, hit.v);
    const InstancePlacement& p = g.instances[hit.instance];
    const glm::vec3 n = shading_normal(g.objects[p.object], hit.triangle, hit.u, hit.v);
    return glm::normalize(apply_normal(p.object_from_world, n));
}

}  // namespace kdpm
