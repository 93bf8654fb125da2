#pragma once
// The closest-hit and any-hit queries every kernel asks of a scene: over its own tree
// (kd_traversal.h) or, for a scene of instances, down the instance BVH, each instance's object
// walked with the ray taken into the object's frame. The map is affine, so the object-frame ray
// keeps the world ray's parameter: t, tmin and tmax mean the same in both frames.
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/geometry/affine.h"
#include "runtime/geometry/box_exit_slack.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/kd_traversal.h"
#include "runtime/geometry/ray.h"
#include "runtime/geometry/triangle_intersect.h"

namespace kdpm {

namespace instance_detail {

KDPM_HD KDPM_INLINE Ray to_object(const InstancePlacement& p, const Ray& ray) {
    return Ray{apply_point(p.object_from_world, ray.origin), ray.tmin, apply_vector(p.object_from_world, ray.direction),
               ray.tmax};
}

// Whether the ray enters a node's box within (tmin, tmax), and where. inv: 1 / direction (inf
// for a zero component; the NaN of 0 * inf fails every compare, so that axis does not refuse).
KDPM_HD KDPM_INLINE bool enter_box(const InstanceNode& n, const glm::vec3& o, const glm::vec3& inv, float tmin,
                                   float tmax, float& t_enter) {
    float t0 = tmin, t1 = tmax;
    for (int a = 0; a < 3; ++a) {
        float tn = (n.lo[a] - o[a]) * inv[a];
        float tf = (n.hi[a] - o[a]) * inv[a];
        if (tn > tf) {
            const float s = tn;
            tn = tf;
            tf = s;
        }
        tf *= kExitSlack;  // rays grazing an edge enter
        if (tn > t0) t0 = tn;
        if (tf < t1) t1 = tf;
    }
    t_enter = t0;
    return t0 <= t1;
}

// Visits the instances whose boxes the ray enters, near first: visit(index, tmax) may lower tmax
// (a closer hit) and returns true to stop. Subtrees entered beyond tmax are skipped.
template <class Visit>
KDPM_HD KDPM_INLINE void walk_instances(const GeometryView& g, const Ray& ray, Visit&& visit) {
    if (g.instance_node_count == 0) return;
    const glm::vec3 inv(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z);
    struct Entry {
        std::uint32_t node;
        float t;
    };
    Entry stack[kMaxInstanceBvhDepth + 1];
    std::uint32_t top = 0;
    float tmax = ray.tmax;
    float t_root;
    if (!enter_box(g.instance_nodes[0], ray.origin, inv, ray.tmin, tmax, t_root)) return;
    stack[top++] = Entry{0, t_root};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.t > tmax) continue;
        const InstanceNode& n = g.instance_nodes[e.node];
        if (n.count != 0) {
            if (visit(n.first, tmax)) return;
            continue;
        }
        float ta, tb;
        const bool a_in = enter_box(g.instance_nodes[n.first], ray.origin, inv, ray.tmin, tmax, ta);
        const bool b_in = enter_box(g.instance_nodes[n.first + 1], ray.origin, inv, ray.tmin, tmax, tb);
        // The far child goes on the stack first, so the near one is walked first.
        if (a_in && b_in) {
            const bool a_first = ta <= tb;
            stack[top++] = a_first ? Entry{n.first + 1, tb} : Entry{n.first, ta};
            stack[top++] = a_first ? Entry{n.first, ta} : Entry{n.first + 1, tb};
        } else if (a_in) {
            stack[top++] = Entry{n.first, ta};
        } else if (b_in) {
            stack[top++] = Entry{n.first + 1, tb};
        }
    }
}

}  // namespace instance_detail

// The closest hit with t in (ray.tmin, ray.tmax), or a Hit with triangle == kNoHit. In a scene of
// instances, hit.instance names the instance and hit.triangle its object's triangle.
KDPM_HD KDPM_INLINE Hit closest_hit(const GeometryView& g, const Ray& ray) {
    if (g.instance_count == 0) return closest_hit_flat(g, ray);
    Hit best = miss(ray.tmax);
    instance_detail::walk_instances(g, ray, [&](std::uint32_t i, float& tmax) {
        const InstancePlacement& p = g.instances[i];
        Ray local = instance_detail::to_object(p, ray);
        local.tmax = tmax;
        Hit h = closest_hit_flat(g.objects[p.object], local);
        if (h.found() && h.t < tmax) {
            h.instance = i;
            best = h;
            tmax = h.t;
        }
        return false;
    });
    return best;
}

// True when any triangle is hit with t in (ray.tmin, ray.tmax): shadow rays, visibility.
KDPM_HD KDPM_INLINE bool occluded(const GeometryView& g, const Ray& ray) {
    if (g.instance_count == 0) return occluded_flat(g, ray);
    bool blocked = false;
    instance_detail::walk_instances(g, ray, [&](std::uint32_t i, float&) {
        const InstancePlacement& p = g.instances[i];
        blocked = occluded_flat(g.objects[p.object], instance_detail::to_object(p, ray));
        return blocked;
    });
    return blocked;
}

// Reference: every triangle tested (of every instance), no tree. For tests and debugging.
KDPM_HD KDPM_INLINE Hit closest_hit_brute_force(const GeometryView& g, const Ray& ray) {
    Hit hit = miss(ray.tmax);
    auto all_triangles = [&](const GeometryView& o, const Ray& r, std::uint32_t instance) {
        for (std::uint32_t i = 0; i < o.triangle_count; ++i) {
            float t, u, v;
            if (intersect_triangle(o.triangles[i], r.origin, r.direction, r.tmin, hit.t, t, u, v))
                hit = Hit{t, i, u, v, instance};
        }
    };
    if (g.instance_count == 0) {
        all_triangles(g, ray, kNoInstance);
        return hit;
    }
    for (std::uint32_t i = 0; i < g.instance_count; ++i)
        all_triangles(g.objects[g.instances[i].object], instance_detail::to_object(g.instances[i], ray), i);
    return hit;
}

}  // namespace kdpm
