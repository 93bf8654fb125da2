#pragma once
// The kernels of stochastic progressive photon mapping (--mode sppm; Hachisuka & Jensen 2009).
// Per pass: SppmVisiblePass traces each pixel's camera ray (jittered anew) through mirrors and
// glass, choosing reflection or refraction by the Fresnel probability as the path tracer does,
// to its first diffuse vertex, the visible point; it adds the emitters seen on the way and the
// direct light there by shadow rays to the pixel's direct sum. SppmGatherPass then adds the pass's
// photons of bounce >= 1 within the pixel's radius and updates its statistics with alpha.
// Direct light is by shadow rays, not by bounce-0 photons, because a pixel-sized radius holds few
// photons and shadow rays give the direct part (most of an image) with far less noise; the two
// are complementary, as in --mode path: a shadow ray never passes glass, so light that reaches
// the visible point through mirrors or glass arrives as photons of bounce >= 1.
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/render/camera.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/passes/camera_path_vertex.h"
#include "runtime/render/passes/trace_pass.h"
#include "runtime/render/sppm/sppm_photon_grid.h"
#include "runtime/render/tile_order.h"
#include "runtime/shading/color.h"
#include "runtime/shading/constants.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"
#include "runtime/shading/direct_light.h"
#include "runtime/shading/ray_offset.h"
#include "runtime/shading/specular.h"
#include "runtime/shading/surface_point.h"

namespace kdpm {

inline constexpr float kSppmAlpha = 2.0f / 3.0f;  // fraction of a pass's photons kept (Hachisuka & Jensen)

// A pixel's statistics, kept across passes.
struct SppmPixel {
    glm::vec3 tau{0.0f};     // flux gathered within the radius, rescaled as the radius shrinks
    float radius2 = 0.0f;
    glm::vec3 direct{0.0f};  // sum over passes of the emitted and direct light
    float photons = 0.0f;    // N: the photon count the statistics stand for
};

// This pass's visible point of a pixel (none when the camera path left the scene or was cut).
struct SppmVisiblePoint {
    glm::vec3 position{0.0f};
    std::uint32_t found = 0;
    glm::vec3 normal{0.0f};  // geometric, on the side the camera ray arrived from
    glm::vec3 weight{0.0f};  // specular throughput times the Lambertian BRDF
};

// Random numbers of a pixel's camera path in one pass: a RandomStream keyed by (pixel, pass) as
// the path index. Counter 2v: the Fresnel choice at vertex v; counter 2v + 1: the shadow rays.
struct SppmVisiblePass {
    GeometryView geometry;
    LightSelection lights;
    PinholeCamera camera;
    FrameBuffersView frame;  // only the AOVs (written by pass 0)
    SppmPixel* pixels = nullptr;
    SppmVisiblePoint* points = nullptr;
    std::uint32_t pass = 0;
    std::uint32_t max_depth = 8;
    std::uint32_t light_samples = 1;
    float epsilon = 1e-4f;

    KDPM_HD void operator()(std::uint64_t item) const {
        const std::uint64_t pixel = tiled_pixel(item, frame.width, frame.height);
        const CameraRay cam = camera.ray_at(pixel, frame.width, pass);
        const std::uint64_t path = (pixel << 32) | pass;

        SppmVisiblePoint point;
        glm::vec3 origin = cam.origin, direction = cam.direction;
        glm::vec3 throughput(1.0f), radiance(0.0f);
        for (std::uint32_t vertex = 0; vertex < max_depth; ++vertex) {
            PathVertex at;
            if (!camera_path_vertex(geometry, camera, frame, pass, pixel, vertex, origin, direction, at)) break;
            const SurfacePoint& s = at.surface;
            const MaterialRecord& m = at.material;
            if (s.front) radiance += throughput * to_vec3(m.emission);
            const glm::vec3 above = offset_origin(s.position, s.geometric_normal, epsilon, true);
            if (is_specular(m)) {
                const SpecularScatter out = scatter_specular(m, direction, s.shading_normal, s.front,
                                                             [&] { return RandomStream{random_seed::sppm, path, 2 * vertex}(0); });
                throughput *= out.weight;
                direction = out.direction;
                origin = out.transmitted ? offset_origin(s.position, s.geometric_normal, epsilon, false) : above;
            } else {
                const glm::vec3 albedo = to_vec3(m.diffuse);
                radiance += throughput * direct_light_with(geometry, lights, above, s.shading_normal, albedo,
                                                           light_samples, RandomStream{random_seed::sppm, path, 2 * vertex + 1});
                point.found = 1;
                point.position = s.position;
                point.normal = s.geometric_normal;
                point.weight = throughput * lambert_brdf(albedo);
                break;
            }
            if (!(max_component(throughput) > 0.0f)) break;
        }
        pixels[pixel].direct += radiance;
        points[pixel] = point;
    }
};

struct SppmGatherPass {
    SppmGridView grid;
    SppmPixel* pixels = nullptr;
    const SppmVisiblePoint* points = nullptr;

    KDPM_HD void operator()(std::uint64_t pixel) const {
        const SppmVisiblePoint& point = points[pixel];
        if (!point.found) return;
        SppmPixel state = pixels[pixel];
        glm::vec3 flux(0.0f);
        float count = 0.0f;
        // Photons on the far side of a thin wall are not this surface's light.
        grid.for_each_within(point.position, state.radius2, [&](const SppmPhoton& p) {
            if (glm::dot(p.normal, point.normal) <= 0.0f) return;
            flux += p.power;
            count += 1.0f;
        });
        if (count == 0.0f) return;
        // Keep alpha of the new photons: the radius shrinks so that N + alpha M photons would
        // fall in the smaller disc, and the flux is scaled by the area kept.
        const float kept = state.photons + kSppmAlpha * count;
        const float radius2 = state.radius2 * kept / (state.photons + count);
        state.tau = (state.tau + point.weight * flux) * (radius2 / state.radius2);
        state.radius2 = radius2;
        state.photons = kept;
        pixels[pixel] = state;
    }
};

// The pixel's radiance after `passes` passes: the mean direct part plus tau / (pi R^2) per pass
// (each pass's photons carry the lights' power divided by that pass's photon count).
KDPM_HD KDPM_INLINE glm::vec3 sppm_radiance(const SppmPixel& p, std::uint32_t passes) {
    const float n = static_cast<float>(passes);
    glm::vec3 indirect(0.0f);
    if (p.radius2 > 0.0f) indirect = p.tau / (n * kPi * p.radius2);
    return p.direct / n + indirect;
}

}  // namespace kdpm
