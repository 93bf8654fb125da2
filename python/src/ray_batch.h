#pragma once
// A batch of rays through the geometry kd-tree on every CPU thread: the loop a C++ program
// writes over closest_hit / occluded, shared by GeometryFile.intersect and the benchmark's C++
// reference, so that the two differ only by what Python adds around it.
#include <cstdint>

#include <glm/vec3.hpp>

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/geometry/instance_hit.h"
#include "runtime/geometry/surface_normal.h"

namespace kdpm::python {

struct RayBatch {
    const float* origins;     // 3 per ray
    const float* directions;  // 3 per ray, any non-zero length (t is in units of it)
    const float* tmax;        // 1 per ray
    std::uint64_t count;
};

struct HitArrays {
    float* t;               // the hit's ray parameter, +inf on a miss
    std::int64_t* triangle; // index into the file's triangles, -1 on a miss
    float* u;
    float* v;
    float* normal;          // 3 per ray: the unit shading normal, 0 on a miss
    std::int64_t* material; // -1 on a miss
};

inline Ray batch_ray(const RayBatch& rays, std::uint64_t i) {
    const float* o = rays.origins + 3 * i;
    const float* d = rays.directions + 3 * i;
    return Ray{glm::vec3(o[0], o[1], o[2]), 0.0f, glm::vec3(d[0], d[1], d[2]), rays.tmax[i]};
}

inline void intersect_batch(const GeometryView& g, const RayBatch& rays, const HitArrays& out) {
    cpu_parallel_for(rays.count, [&](std::uint64_t i) {
        const Hit hit = closest_hit(g, batch_ray(rays, i));
        float* n = out.normal + 3 * i;
        if (!hit.found()) {
            out.t[i] = __builtin_inff();
            out.triangle[i] = -1;
            out.u[i] = out.v[i] = 0.0f;
            n[0] = n[1] = n[2] = 0.0f;
            out.material[i] = -1;
            return;
        }
        out.t[i] = hit.t;
        out.triangle[i] = hit.triangle;
        out.u[i] = hit.u;
        out.v[i] = hit.v;
        const glm::vec3 s = world_shading_normal(g, hit);
        n[0] = s.x;
        n[1] = s.y;
        n[2] = s.z;
        out.material[i] = object_of(g, hit).triangles[hit.triangle].material;
    }, 256);
}

inline void occluded_batch(const GeometryView& g, const RayBatch& rays, bool* out) {
    cpu_parallel_for(rays.count, [&](std::uint64_t i) { out[i] = occluded(g, batch_ray(rays, i)); }, 256);
}

}  // namespace kdpm::python
