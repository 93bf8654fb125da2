#pragma once
// Pass 2 of a frame sample in mode final-gather (Jensen's final gathering): at each diffuse
// vertex, the caustics from the caustic map plus the indirect light of N cosine-distributed
// gather rays. A gather ray is followed through mirrors and glass to its first diffuse hit,
// where the light leaving toward the vertex is read as gather_lookup.h says: by default albedo /
// pi times the irradiance precomputed at the nearest chosen photon of the .kdp's irradiance map
// (one k = 1 search), or, without that map or without a chosen photon near the hit, the global
// map's k-nearest estimate. The gather hit's estimate counts every photon (direct ones included),
// so the vertex sees light of one diffuse bounce more than the photon map's bounce count.
// Emitters met by gather rays add nothing: direct light comes from the shadow rays of the
// shade pass, and light through mirrors and glass from the caustic map.
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/photons/irradiance_lookup.h"
#include "runtime/photons/radiance_estimate.h"
#include "runtime/render/final_gather/gather_lookup.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/passes/path_walk.h"
#include "runtime/render/passes/photon_gather_pass.h"
#include "runtime/render/passes/trace_pass.h"
#include "runtime/render/render_settings.h"
#include "runtime/render/tile_order.h"
#include "runtime/shading/color.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"
#include "runtime/shading/direct_light.h"
#include "runtime/shading/ray_offset.h"
#include "runtime/shading/specular.h"
#include "runtime/shading/surface_point.h"

namespace kdpm {

struct FinalGatherPass {

    GeometryView geometry;
    LightSelection lights;                  // the path lookup's shadow rays
    FrameBuffersView frame;
    PhotonMaps maps;
    RadianceEstimateParams hit_params;      // the k-nearest estimate at a gather hit: every photon; its
                                            // plane_distance also bounds the irradiance map's lookup
    RadianceEstimateParams caustic_params;  // the caustic map at the pixel's vertices
    float lookup_radius = 0.0f;             // nearest chosen photon within this (<= 0: unlimited)
    GatherLookup lookup = GatherLookup::irradiance_map;
    std::uint32_t sample = 0;
    std::uint32_t gather_rays = 64;
    std::uint32_t max_depth = 8;            // rays in a run of mirror/glass bounces, as in the other modes
    float epsilon = 1e-4f;

    KDPM_HD void operator()(std::uint64_t item) const {
        const std::uint64_t pixel = tiled_pixel(item, frame.width, frame.height);
        const std::uint32_t count = frame.vertex_count[pixel];
        KnnHeap heap;
        for (std::uint32_t i = 0; i < count && i < kMaxDiffuseVertices; ++i) gather_vertex(pixel, i, heap);
    }

    // Caustics plus the gather rays' indirect light at the pixel's vertex i, into frame.gathered.
    KDPM_HD void gather_vertex(std::uint64_t pixel, std::uint32_t i, KnnHeap& heap) const {
        const std::uint64_t slot = frame.vertex_slot(pixel, i);
        const DiffuseVertex& v = frame.vertices[slot];
        glm::vec3 l(0.0f);
        if (maps.caustic.node_count > 0)
            l += estimate_radiance(maps.caustic, v.position, v.shading_normal, v.albedo, caustic_params, heap)
                     .radiance;
        const std::uint32_t rays =
            gather_rays < 1 ? 1 : (gather_rays > kMaxGatherRays ? kMaxGatherRays : gather_rays);
        glm::vec3 sum(0.0f);
        for (std::uint32_t r = 0; r < rays; ++r) sum += gather(v, (pixel << 32) | sample, (i << 16) | r, heap);
        // Cosine sampling: f_r L cos / pdf = albedo L per ray.
        l += v.albedo * sum / static_cast<float>(rays);
        frame.gathered[slot] = l;
    }

    // The radiance arriving at the vertex along one gather ray.
    KDPM_HD glm::vec3 gather(const DiffuseVertex& v, std::uint64_t path, std::uint32_t ray_index, KnnHeap& heap) const {
        const RandomStream random{random_seed::gather, path, ray_index};
        // About the geometric normal, as the photon shooter bounces (diffuse.h says why).
        glm::vec3 direction = cosine_direction(v.geometric_normal, random(0), random(1));
        if (glm::dot(direction, v.geometric_normal) <= 0.0f) return glm::vec3(0.0f);  // grazing
        float distance = 0.0f;
        return follow(v, direction, path, ray_index, heap, distance);
    }

    // The radiance arriving at the vertex from `direction`, and the distance to the first
    // surface that way (infinity on a miss; irradiance caching's record radius).
    KDPM_HD glm::vec3 follow(const DiffuseVertex& v, glm::vec3 direction, std::uint64_t path, std::uint32_t ray_index,
                             KnnHeap& heap, float& distance) const {
        const RandomStream random{random_seed::gather, path, ray_index};
        distance = std::numeric_limits<float>::infinity();
        glm::vec3 origin = offset_origin(v.position, v.geometric_normal, epsilon, true);
        glm::vec3 throughput(1.0f);
        for (std::uint32_t depth = 0; depth < max_depth; ++depth) {
            PathVertex at;
            if (!path_vertex(geometry, origin, direction, at)) return glm::vec3(0.0f);
            if (depth == 0) distance = at.hit.t;
            const SurfacePoint& s = at.surface;
            if (is_specular(at.material)) {
                const SpecularScatter out =
                    scatter_specular(at.material, direction, s.shading_normal, s.front, [&] { return random(2 + depth); });
                throughput *= out.weight;
                direction = out.direction;
                origin = offset_origin(s.position, s.geometric_normal, epsilon, !out.transmitted);
            } else {
                return throughput * diffuse_radiance(at, direction, path, ray_index, heap);
            }
            if (!(max_component(throughput) > 0.0f)) return glm::vec3(0.0f);
        }
        return glm::vec3(0.0f);
    }

    // The random numbers of the path lookup's walk: its vertex v reads dimensions from v times a
    // walk's count on, in a stream of its own per gather ray.
    struct WalkStream {
        RandomStream ray;
        std::uint32_t first;
        KDPM_HD float operator()(std::uint32_t dimension) const { return ray(first + dimension); }
    };

    // The light leaving a diffuse gather hit toward the gathering point (see the file comment;
    // the hit's own emission is the shade pass's direct light).
    KDPM_HD glm::vec3 diffuse_radiance(const PathVertex& at, glm::vec3 direction, std::uint64_t path,
                                       std::uint32_t ray_index, KnnHeap& heap) const {
        const SurfacePoint& s = at.surface;
        const glm::vec3 albedo = to_vec3(at.material.diffuse);
        if (lookup == GatherLookup::path) {
            const PathWalk walk{geometry, lights, max_depth, 0u, epsilon};
            const RandomStream ray{random_seed::gather_path, path, ray_index};
            return walk.radiance(
                at, direction, false,
                [&](std::uint32_t vertex) { return WalkStream{ray, vertex * kPathWalkDimensions}; },
                [&](std::uint32_t, const glm::vec3& o, const glm::vec3& d, PathVertex& out) {
                    return path_vertex(geometry, o, d, out);
                });
        }
        // The photons' normals are their triangles' (photon_path.h): the hit's geometric normal is
        // what they agree with, and the plane the test measures heights from.
        const glm::vec3 n = s.geometric_normal;
        glm::vec3 irradiance(0.0f);
        if (lookup == GatherLookup::irradiance_map && maps.irradiance.present() &&
            lookup_irradiance(maps.irradiance, s.position, n, lookup_radius, hit_params.min_normal_cos,
                              hit_params.plane_distance, heap, irradiance))
            return lambert_brdf(albedo) * irradiance;
        return estimate_radiance(maps.global, s.position, n, albedo, hit_params, heap).radiance;
    }
};

// From the gather pass the settings made (its maps and estimate parameters): the hit estimate
// counts every photon of the global map, the nearest chosen photon is looked for as far as the
// k-nearest search would go, and both read only photons near the hit's tangent plane.
inline FinalGatherPass make_final_gather_pass(const GeometryView& geometry, const LightSelection& lights,
                                              const PhotonGatherPass& gather, std::uint32_t sample,
                                              const RenderSettings& settings, float epsilon) {
    FinalGatherPass pass;
    pass.geometry = geometry;
    pass.lights = lights;
    pass.frame = gather.frame;
    pass.maps = gather.maps;
    pass.hit_params = gather.global_params;
    pass.hit_params.min_bounce = 0;
    pass.hit_params.exclude_flags = 0;
    pass.caustic_params = gather.caustic_params;
    pass.lookup_radius = gather.global_params.max_radius;
    pass.hit_params.plane_distance = kPlaneDistanceFactor * gather.maps.typical_radius;
    pass.lookup = settings.gather_lookup;
    pass.sample = sample;
    pass.gather_rays = settings.gather_rays;
    pass.max_depth = settings.max_depth;
    pass.epsilon = epsilon;
    return pass;
}

}  // namespace kdpm
