#pragma once
// One photon path, the shooting kernel (CPU and GPU): emitted from a light chosen by power, at a
// uniform point, in a cosine-distributed direction about the light normal; traced through the
// geometry kd-tree; stored at every diffuse hit; continued by the material (diffuse: cosine
// bounce; mirror: reflection; glass: Fresnel reflection or refraction) with Russian roulette on
// the reflectance, for at most max_bounces bounces. All randomness is counter_random(seed,
// path, bounce, dimension), so the path is a pure function of its index. The closest-hit query
// is a parameter (the kd-tree walk by default) so that a bench peer can run the very same path
// rules over another intersector. A path is its emission (start_photon_path) and then one step per
// ray (continue_photon_path): trace_photon_path takes the steps of one path in a row, the CPU
// shooter takes one step of many paths at a time (shoot_waves.h); the hits are the same.
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "formats/photon_layout.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/geometry/surface_normal.h"
#include "runtime/shading/area_light.h"
#include "runtime/shading/color.h"
#include "runtime/shading/constants.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"
#include "runtime/shading/ray_offset.h"
#include "runtime/shading/specular.h"
#include "runtime/shading/surface_point.h"

namespace kdpm {

struct ShootSettings {
    std::uint64_t emitted_count = 0;  // N: every path starts with (light power) / (N p(light))
    std::uint32_t max_bounces = 4;    // stored hits have bounce 0..max_bounces
    std::uint32_t seed = 0;
    float ray_offset = 1e-4f;         // origin offset off a surface (scene units)
};

struct PhotonPathResult {
    std::uint32_t stored = 0;  // hits written to out[0..stored)
    std::uint32_t rays = 0;    // closest-hit queries traced
};

namespace photon_path_detail {

KDPM_HD KDPM_INLINE void put3(float (&dst)[3], const glm::vec3& v) {
    dst[0] = v.x;
    dst[1] = v.y;
    dst[2] = v.z;
}

}  // namespace photon_path_detail

// The geometry kd-tree's closest hit: the intersector of every kdpm shooter.
struct KdTreeClosestHit {
    KDPM_HD KDPM_INLINE Hit operator()(const GeometryView& g, const Ray& ray) const { return closest_hit(g, ray); }
};

// A path between two rays: where its next ray starts and goes, and the power it carries. Plain
// data without initialisers (start_photon_path sets every field), so that a wave's arrays of
// them are not cleared before they are written.
struct PhotonPathState {
    glm::vec3 origin, direction, power;
    std::uint64_t path;
    std::uint32_t bounce;         // of the next hit
    std::uint16_t stored;         // hits stored so far (at most max_bounces + 1 <= 256)
    std::uint16_t specular_only;  // no diffuse hit yet: a diffuse hit after bounce 0 is caustic
};

// Whether paths can start at all: a light with power, and photons to share it. Where not, a path
// traces nothing and stores nothing.
KDPM_HD KDPM_INLINE bool photons_can_start(const LightSelection& lights, const ShootSettings& s) {
    return lights.count > 0 && lights.total_power > 0.0f && s.emitted_count > 0;
}

// Emission of path `path` (bounce stream 0, dimensions 0..4); photons_can_start must hold.
KDPM_HD inline PhotonPathState start_photon_path(const GeometryView& g, const LightSelection& lights,
                                                 const ShootSettings& s, std::uint64_t path) {
    auto rnd = [&](std::uint32_t dim) { return counter_random(s.seed, path, 0, dim); };
    const AreaLightRecord& light = g.lights[pick_light(lights, rnd(0))];
    const glm::vec3 emit_normal = light_normal(light);
    const float u1 = rnd(1), u2 = rnd(2);
    PhotonPathState st;
    st.path = path;
    st.bounce = 0;
    st.stored = 0;
    st.specular_only = 1;
    st.direction = cosine_direction(emit_normal, rnd(3), rnd(4));
    st.origin = offset_origin(point_on_light(light, u1, u2), emit_normal, s.ray_offset, true);
    // Flux pi A L of this light over the probability of choosing it, shared by N paths. (The
    // probability is power / total rather than pick_probability's cdf difference: equal but for
    // rounding, and the photon files made so far are a function of this one.)
    const float choose = light.power / lights.total_power;
    st.power = (kPi * light.area / (choose * static_cast<float>(s.emitted_count))) * to_vec3(light.radiance);
    return st;
}

// The path's next ray as the closest-hit query takes it.
KDPM_HD KDPM_INLINE Ray next_photon_ray(const PhotonPathState& st) {
    return Ray{st.origin, 0.0f, st.direction, 3.402823466e38f};
}

// What the path does at `hit` (the closest hit of next_photon_ray(st)): at a diffuse surface
// writes the stored hit to *stored and sets `wrote`; then either goes on (st set for the next
// ray; returns true) or ends (a miss, Russian roulette, the bounce limit; returns false).
KDPM_HD inline bool continue_photon_path(const GeometryView& g, const ShootSettings& s, const Hit& hit,
                                         PhotonPathState& st, PhotonHit* stored, bool& wrote) {
    using namespace photon_path_detail;
    wrote = false;
    if (!hit.found()) return false;
    const std::uint64_t path = st.path;
    const std::uint32_t bounce = st.bounce;
    glm::vec3 direction = st.direction;
    auto rnd = [&](std::uint32_t stream, std::uint32_t dim) { return counter_random(s.seed, path, stream, dim); };
    const TriangleRecord tri = world_triangle(g, hit);
    const glm::vec3 p = surface_point(tri, hit.u, hit.v);
    const glm::vec3 ng = geometric_normal(tri);
    const bool front = glm::dot(direction, ng) < 0.0f;
    const glm::vec3 n = front ? ng : -ng;  // the side the photon arrived from
    const MaterialRecord m = material_of(g, hit);
    const auto kind = static_cast<MaterialKind>(m.kind);
    const std::uint32_t stream = bounce + 1;
    const float u_rr = rnd(stream, 0);

    if (kind == MaterialKind::mirror) {
        if (bounce >= s.max_bounces || !russian_roulette(st.power, to_vec3(m.specular), u_rr)) return false;
        direction = glm::normalize(reflect_dir(direction, n));
    } else if (kind == MaterialKind::glass) {
        glm::vec3 refracted(0.0f);
        const float fresnel = glass_fresnel(m, direction, n, front, refracted);
        if (bounce >= s.max_bounces) return false;
        if (rnd(stream, 3) < fresnel) {
            direction = glm::normalize(reflect_dir(direction, n));
        } else {
            if (!russian_roulette(st.power, to_vec3(m.transmission), u_rr)) return false;
            direction = refracted;
        }
    } else {
        PhotonHit& h = *stored;
        put3(h.position, p);
        h.flags = make_photon_flags(bounce, st.specular_only != 0 && bounce > 0);
        put3(h.power, st.power);
        h.path = static_cast<std::uint32_t>(path);
        put3(h.direction, direction);
        h.reserved0 = 0;
        put3(h.normal, n);
        h.reserved1 = 0;
        wrote = true;
        st.specular_only = 0;
        if (bounce >= s.max_bounces || !russian_roulette(st.power, to_vec3(m.diffuse), u_rr)) return false;
        direction = cosine_direction(n, rnd(stream, 1), rnd(stream, 2));
    }
    // Leave the surface on the side the new direction points to.
    st.origin = offset_origin(p, ng, s.ray_offset, glm::dot(direction, ng) >= 0.0f);
    st.direction = direction;
    st.bounce = bounce + 1;
    return true;
}

// Traces path `path` depth first; `out` has room for max_bounces + 1 hits. intersect(g, ray)
// returns the closest Hit (triangle index into g.triangles, barycentrics u, v of v1 and v2) or a
// miss.
template <class ClosestHit = KdTreeClosestHit>
KDPM_HD inline PhotonPathResult trace_photon_path(const GeometryView& g, const LightSelection& lights,
                                                  const ShootSettings& s, std::uint64_t path, PhotonHit* out,
                                                  const ClosestHit& intersect = ClosestHit{}) {
    PhotonPathResult result;
    if (!photons_can_start(lights, s)) return result;
    PhotonPathState st = start_photon_path(g, lights, s, path);
    for (;;) {
        const Hit hit = intersect(g, next_photon_ray(st));
        ++result.rays;
        bool wrote;
        const bool goes_on = continue_photon_path(g, s, hit, st, out + result.stored, wrote);
        result.stored += wrote ? 1u : 0u;
        if (!goes_on) return result;
    }
}

}  // namespace kdpm
