#pragma once
// The reference mode (--mode path): per pixel and sample, one camera path traced to its end in
// a single pass. At each diffuse vertex, next-event estimation (one shadow ray to a light picked
// by power, direct_light_with), then a cosine-distributed bounce with Russian roulette on the
// albedo; mirrors reflect, glass reflects or refracts with the Fresnel probability. Emission
// met by a ray counts only on the camera ray and after mirror/glass bounces: after a diffuse
// bounce the light it hits was already sampled by that vertex's shadow ray, so counting it
// again would double it. Unbiased but for the bounce limits the settings ask for.
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/kd_traversal.h"
#include "runtime/render/camera.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/passes/camera_path_vertex.h"
#include "runtime/render/passes/trace_pass.h"
#include "runtime/render/tile_order.h"
#include "runtime/shading/color.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"
#include "runtime/shading/direct_light.h"
#include "runtime/shading/ray_offset.h"
#include "runtime/shading/specular.h"
#include "runtime/shading/surface_point.h"

namespace kdpm {

// Random numbers of a camera path: a RandomStream keyed by (pixel, sample) as the 64-bit path
// index and the vertex as the bounce, so every value is a pure function of
// (pixel, sample, bounce, dimension). Dimensions per vertex: 0..2 the shadow ray, 3 roulette,
// 4..5 the diffuse direction, 6 the Fresnel choice.
struct PathPass {
    // A hard end for paths roulette would not stop (an albedo-1 room has no way out); reached
    // with probability rho^1024 otherwise.
    static constexpr std::uint32_t kMaxVertices = 1024;

    GeometryView geometry;
    LightSelection lights;
    PinholeCamera camera;
    FrameBuffersView frame;
    std::uint32_t sample = 0;
    std::uint32_t max_depth = 8;    // rays in a run of mirror/glass bounces, as in the other modes
    std::uint32_t max_bounces = 0;  // diffuse vertices shaded per path; 0: unlimited (roulette ends it)
    float epsilon = 1e-4f;

    KDPM_HD void operator()(std::uint64_t item) const {
        const std::uint64_t pixel = tiled_pixel(item, frame.width, frame.height);
        const CameraRay cam = camera.ray_at(pixel, frame.width, sample);
        const std::uint64_t path = (pixel << 32) | sample;

        glm::vec3 origin = cam.origin, direction = cam.direction;
        glm::vec3 throughput(1.0f), radiance(0.0f);
        bool count_emission = true;     // the last vertex was the camera or a mirror/glass
        std::uint32_t run_depth = 0;    // rays since the camera or the last diffuse vertex
        std::uint32_t diffuse = 0;
        for (std::uint32_t vertex = 0; vertex < kMaxVertices; ++vertex) {
            PathVertex at;
            if (!camera_path_vertex(geometry, camera, frame, sample, pixel, vertex, origin, direction, at)) break;
            const SurfacePoint& s = at.surface;
            const MaterialRecord& m = at.material;
            if (count_emission && s.front) radiance += throughput * to_vec3(m.emission);
            const RandomStream random{random_seed::path, path, vertex};
            const glm::vec3 above = offset_origin(s.position, s.geometric_normal, epsilon, true);

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
        }
        frame.accum[pixel] += radiance;
    }
};

}  // namespace kdpm
