#pragma once
// Stack-based front-to-back traversal of the SAH geometry kd-tree: closest hit and any-hit
// (occlusion). The ray is first clipped to the scene bounds; inner nodes are visited near
// child first, the far child is pushed only when the segment crosses the split plane, and the
// walk stops as soon as a hit lies within the current leaf's segment. On x86-64 CPUs a leaf's
// triangles are tested four at a time (leaf_triangles_simd.h), with the same results.
#include <cassert>
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/leaf_triangles_simd.h"
#include "runtime/geometry/ray.h"
#include "runtime/geometry/triangle_intersect.h"
#include "runtime/geometry/wide_traversal.h"

namespace kdpm {

namespace kd_detail {

// Clips [t0, t1] to the slab intersection of the scene bounds. NaN slab values (origin on a
// slab plane with a zero direction component) leave the interval unchanged.
KDPM_HD KDPM_INLINE bool clip_to_bounds(const GeometryInfo& info, const glm::vec3& origin,
                                        const glm::vec3& inv_dir, float& t0, float& t1) {
    for (int a = 0; a < 3; ++a) {
        float tn = (info.bounds_min[a] - origin[a]) * inv_dir[a];
        float tf = (info.bounds_max[a] - origin[a]) * inv_dir[a];
        if (tn > tf) {
            float s = tn;
            tn = tf;
            tf = s;
        }
        if (tn > t0) t0 = tn;
        if (tf < t1) t1 = tf;
    }
    return t0 <= t1;
}

// Whether a ray from coordinate o (on the node's axis) meets the "below" child first; a ray
// starting on the plane goes below when its direction there is not up. Shared by the packet walk,
// whose lanes must order children exactly as this walk does.
KDPM_HD KDPM_INLINE bool below_first(float o, float split, bool dir_not_up) {
    return o < split || (o == split && dir_not_up);
}

// Walks the tree; for each leaf calls visit(first, count, t_leaf_max), which returns true to
// stop the walk; visit.limit() is the farthest t still of interest. Shared by the closest-hit
// and any-hit queries.
template <class LeafVisitor>
KDPM_HD KDPM_INLINE void walk(const GeometryView& g, const Ray& ray, LeafVisitor& visit) {
    if (g.node_count == 0) return;
    const glm::vec3 inv_dir(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z);
    float tmin = ray.tmin, tmax = ray.tmax;
    if (!clip_to_bounds(g.info, ray.origin, inv_dir, tmin, tmax)) return;

    // At most one entry per inner node on the current path. GeometryFile's validator refuses
    // trees deeper than kMaxKdTreeDepth, so the guard below never drops a push for a loaded
    // file; debug builds assert it (a hand-built view that breaks the limit would lose subtrees).
    // One array per field: each pop then reads what one store of the push wrote. As one struct,
    // the compiler stores the node and the segment apart and reads them back as node + tmin and
    // tmax, a load spanning two stores that the store buffer cannot forward, a stall on nearly
    // every pop that follows its push closely.
    std::uint32_t stack_node[kMaxKdDepth];
    float stack_tmin[kMaxKdDepth], stack_tmax[kMaxKdDepth];
    std::uint32_t sp = 0;
    std::uint32_t node = 0;
    // Plain arrays for the per-node axis lookups: glm's vec3 operator[] is a switch.
    const float org[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const float inv[3] = {inv_dir.x, inv_dir.y, inv_dir.z};
    const bool dir_not_up[3] = {ray.direction.x <= 0.0f, ray.direction.y <= 0.0f, ray.direction.z <= 0.0f};
    for (;;) {
        KdNode n = g.nodes[node];
        while (!n.is_leaf()) {
            const int axis = n.axis();
            const float split = n.split();
            const float o = org[axis];
            const float tplane = (split - o) * inv[axis];
            const bool near_below = below_first(o, split, dir_not_up[axis]);
            const std::uint32_t below = node + 1, above = n.above_child();
            const std::uint32_t first = near_below ? below : above;
            const std::uint32_t second = near_below ? above : below;
            // NaN (ray inside the plane) and planes behind or beyond the segment: near side only.
            if (!(tplane <= tmax) || tplane <= 0.0f) {
                node = first;
            } else if (tplane < tmin) {
                node = second;
            } else if (const KdNode f = g.nodes[first]; f.is_leaf() && f.count() == 0) {
                // An empty near leaf (most leaves a ray meets are empty): what visiting it
                // and popping the far side would do, without the push, the trip out of this loop
                // and the pop. Same decisions, in the same order.
                if (visit(f.first(), 0, tplane) || tplane > visit.limit()) return;
                node = second;
                tmin = tplane;
            } else {
                assert(sp < kMaxKdDepth && "kd-tree deeper than kMaxKdTreeDepth");
#if defined(__CUDA_ARCH__)
                const bool far_empty = false;
#else
                // An empty far leaf is not pushed. Visiting it could only stop the walk where the
                // next pop stops it anyway (the next entry starts where its segment ends), or,
                // at an exact tie, leave leaves to visit that cannot hold a nearer hit: the same
                // hits. On a CPU it speeds photon shooting and costs primary and shadow rays
                // nothing; GPU builds leave it out, as there it adds a load of unknown cost.
                const KdNode far = g.nodes[second];
                const bool far_empty = far.is_leaf() && far.count() == 0;
#endif
                if (sp < kMaxKdDepth && !far_empty) {
                    stack_node[sp] = second;
                    stack_tmin[sp] = tplane;
                    stack_tmax[sp] = tmax;
                    ++sp;
                }
                node = first;
                tmax = tplane;
            }
            n = g.nodes[node];
        }
        if (visit(n.first(), n.count(), tmax)) return;
        if (sp == 0) return;
        --sp;
        // Entries come off nearest first: once one starts beyond the best hit, all do.
        if (stack_tmin[sp] > visit.limit()) return;
        node = stack_node[sp];
        tmin = stack_tmin[sp];
        tmax = stack_tmax[sp];
    }
}

struct ClosestVisitor {
    const GeometryView& g;
    const Ray& ray;
    Hit hit;
    KDPM_HD float limit() const { return hit.t; }
    KDPM_HD bool operator()(std::uint32_t first, std::uint32_t count, float leaf_tmax) {
#if defined(KDPM_LEAF_SIMD)
        closest_in_leaf(g, ray, first, count, hit);
#else
        for (std::uint32_t i = 0; i < count; ++i) {
            const std::uint32_t tri = g.leaf_indices[first + i];
            float t, u, v;
            if (intersect_triangle(g.triangles[tri], ray.origin, ray.direction, ray.tmin, hit.t, t, u, v))
                hit = Hit{t, tri, u, v};
        }
#endif
        // A hit inside this leaf's segment cannot be beaten by leaves further along the ray.
        return hit.found() && hit.t <= leaf_tmax;
    }
};

struct AnyVisitor {
    const GeometryView& g;
    const Ray& ray;
    bool occluded;
    KDPM_HD float limit() const { return ray.tmax; }
    KDPM_HD bool operator()(std::uint32_t first, std::uint32_t count, float) {
#if defined(KDPM_LEAF_SIMD)
        occluded = any_in_leaf(g, ray, first, count);
        return occluded;
#else
        for (std::uint32_t i = 0; i < count; ++i) {
            float t, u, v;
            if (intersect_triangle(g.triangles[g.leaf_indices[first + i]], ray.origin, ray.direction, ray.tmin,
                                   ray.tmax, t, u, v)) {
                occluded = true;
                return true;
            }
        }
        return false;
#endif
    }
};

}  // namespace kd_detail

// The closest hit with t in (ray.tmin, ray.tmax), or a Hit with triangle == kNoHit, by the
// binary walk of geometry.nodes.
KDPM_HD KDPM_INLINE Hit closest_hit_kd(const GeometryView& g, const Ray& ray) {
    kd_detail::ClosestVisitor visitor{g, ray, miss(ray.tmax)};
    kd_detail::walk(g, ray, visitor);
    return visitor.hit;
}

// True when any triangle is hit with t in (ray.tmin, ray.tmax), by the binary walk.
KDPM_HD KDPM_INLINE bool occluded_kd(const GeometryView& g, const Ray& ray) {
    kd_detail::AnyVisitor visitor{g, ray, false};
    kd_detail::walk(g, ray, visitor);
    return visitor.occluded;
}

// The closest hit with t in (ray.tmin, ray.tmax) among g's own triangles, or a Hit with
// triangle == kNoHit: on the CPU over the wide tree where the file has one (format 1.2), else
// (and on the GPU) the binary walk. closest_hit (scene_traversal.h) adds instances.
KDPM_HD KDPM_INLINE Hit closest_hit_flat(const GeometryView& g, const Ray& ray) {
#if !defined(__CUDA_ARCH__)
    if (g.wide != nullptr) return closest_hit_wide(g, ray);
#endif
    return closest_hit_kd(g, ray);
}

// True when any of g's own triangles is hit with t in (ray.tmin, ray.tmax), by the same choice of
// walk as closest_hit_flat.
KDPM_HD KDPM_INLINE bool occluded_flat(const GeometryView& g, const Ray& ray) {
#if !defined(__CUDA_ARCH__)
    if (g.wide != nullptr) return occluded_wide(g, ray);
#endif
    return occluded_kd(g, ray);
}

}  // namespace kdpm
