#pragma once
// A surface interaction in the form every pass uses, and the material at a hit.
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/instance_hit.h"
#include "runtime/geometry/ray.h"
#include "runtime/geometry/surface_normal.h"
#include "runtime/shading/texture_lookup.h"

namespace kdpm {

struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 shading_normal;    // facing the incoming ray
    glm::vec3 geometric_normal;  // facing the incoming ray
    bool front;                  // the ray hit the side cross(e1, e2) points to
};

// The hit of `ray`, at its ray parameter.
KDPM_HD KDPM_INLINE SurfacePoint surface_at(const GeometryView& g, const Ray& ray, const Hit& hit) {
    const glm::vec3 ng = geometric_normal(world_triangle(g, hit));
    glm::vec3 ns = world_shading_normal(g, hit);
    SurfacePoint s;
    s.front = glm::dot(ng, ray.direction) < 0.0f;
    s.geometric_normal = s.front ? ng : -ng;
    if (glm::dot(ns, s.geometric_normal) < 0.0f) ns = -ns;
    s.shading_normal = ns;
    s.position = ray.origin + hit.t * ray.direction;
    return s;
}

// The material at a hit, its diffuse colour read from its texture when it has one (the one
// place every pass and the photon shooter take the albedo from); mid grey for an index past the
// table (a hand-built scene without materials; a loaded file's indices are all checked).
// `uv_footprint`: the filter width in texture coordinates, 0 when unknown (finest level).
KDPM_HD KDPM_INLINE MaterialRecord material_of(const GeometryView& scene, const Hit& hit, float uv_footprint = 0.0f) {
    const GeometryView& g = object_of(scene, hit);
    const std::uint32_t index = g.triangles[hit.triangle].material;
    MaterialRecord m{};
    if (index < g.material_count) {
        m = g.materials[index];
    } else {
        m.diffuse[0] = m.diffuse[1] = m.diffuse[2] = 0.5f;
        return m;
    }
    if (const TextureRecord* t = diffuse_texture_of(g, m)) {
        const glm::vec3 albedo = texture_lookup(g.texels, *t, uv_at(g.uvs[hit.triangle], hit.u, hit.v), uv_footprint);
        m.diffuse[0] = albedo.x, m.diffuse[1] = albedo.y, m.diffuse[2] = albedo.z;
    }
    return m;
}

}  // namespace kdpm
