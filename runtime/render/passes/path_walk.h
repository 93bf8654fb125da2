#pragma once
// The walk of a path tracer from one vertex on, shared by --mode path (from the camera) and the
// final gather's path-traced continuation (from a gather hit): at each diffuse vertex,
// next-event estimation (one shadow ray to a light picked by power), then a cosine-distributed
// bounce with Russian roulette on the albedo; mirrors reflect, glass reflects or refracts with
// the Fresnel probability. Emission met by a ray counts only where the walk says so at its start
// and after mirror/glass bounces: after a diffuse bounce the light it hits was already sampled by
// that vertex's shadow ray, so counting it again would double it.
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/render/passes/camera_path_vertex.h"
#include "runtime/shading/color.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"
#include "runtime/shading/direct_light.h"
#include "runtime/shading/ray_offset.h"
#include "runtime/shading/specular.h"
#include "runtime/shading/surface_point.h"

namespace kdpm {

// Dimensions a walk reads per vertex: 0..2 the shadow ray, 3 roulette, 4..5 the diffuse
// direction, 6 the Fresnel choice.
inline constexpr std::uint32_t kPathWalkDimensions = 7;

struct PathWalk {
    // A hard end for paths roulette would not stop (an albedo-1 room has no way out); reached
    // with probability rho^1024 otherwise.
    static constexpr std::uint32_t kMaxVertices = 1024;

    GeometryView geometry;
    LightSelection lights;
    std::uint32_t max_depth = 8;    // rays in a run of mirror/glass bounces
    std::uint32_t max_bounces = 0;  // diffuse vertices shaded; 0: unlimited (roulette ends it)
    float epsilon = 1e-4f;

    // The radiance the walk gathers from vertex `at`, reached along `direction`, on. stream(v):
    // the random numbers of the walk's vertex v (callable with a dimension); next(v, origin,
    // direction, out): the walk's vertex v (> 0) along that ray, false where the ray leaves the
    // scene. count_emission: whether `at`'s own emission counts.
    template <class Stream, class Next>
    KDPM_HD glm::vec3 radiance(PathVertex at, glm::vec3 direction, bool count_emission, Stream&& stream,
                               Next&& next) const {
        glm::vec3 throughput(1.0f), radiance(0.0f);
        std::uint32_t run_depth = 0;  // rays since the walk's start or the last diffuse vertex
        std::uint32_t diffuse = 0;
        for (std::uint32_t vertex = 0; vertex < kMaxVertices; ++vertex) {
            const SurfacePoint& s = at.surface;
            const MaterialRecord& m = at.material;
            if (count_emission && s.front) radiance += throughput * to_vec3(m.emission);
            const auto random = stream(vertex);
            const glm::vec3 above = offset_origin(s.position, s.geometric_normal, epsilon, true);
            glm::vec3 origin;
            if (is_specular(m)) {
                if (run_depth + 1 >= max_depth) break;
                ++run_depth;
                const SpecularScatter out =
                    scatter_specular(m, direction, s.shading_normal, s.front, [&] { return random(6); });
                throughput *= out.weight;
                direction = out.direction;
                origin = out.transmitted ? offset_origin(s.position, s.geometric_normal, epsilon, false) : above;
                count_emission = true;
            } else {
                const glm::vec3 albedo = to_vec3(m.diffuse);
                radiance += throughput * direct_light_with(geometry, lights, above, s.shading_normal, albedo, 1u, random);
                ++diffuse;
                if (max_bounces != 0 && diffuse >= max_bounces) break;
                if (!russian_roulette(throughput, albedo, random(3))) break;
                // About the geometric normal, as the photon shooter bounces (diffuse.h says why).
                direction = cosine_direction(s.geometric_normal, random(4), random(5));
                if (glm::dot(direction, s.geometric_normal) <= 0.0f) break;  // grazing, no light
                origin = above;
                run_depth = 0;
                count_emission = false;
            }
            if (!(max_component(throughput) > 0.0f)) break;
            if (vertex + 1 >= kMaxVertices || !next(vertex + 1, origin, direction, at)) break;
        }
        return radiance;
    }
};

// A walk's vertex from a plain closest hit (no AOVs, the texture's finest level).
KDPM_HD KDPM_INLINE bool path_vertex(const GeometryView& geometry, const glm::vec3& origin, const glm::vec3& direction,
                                     PathVertex& out) {
    const Ray ray{origin, 0.0f, direction, std::numeric_limits<float>::infinity()};
    out.hit = closest_hit(geometry, ray);
    if (!out.hit.found()) return false;
    out.surface = surface_at(geometry, ray, out.hit);
    out.material = material_of(geometry, out.hit, 0.0f);
    return true;
}

}  // namespace kdpm
