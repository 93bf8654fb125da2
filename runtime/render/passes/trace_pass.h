#pragma once
// Pass 1 of a frame sample: the camera ray of each pixel, followed through mirrors and glass
// (a small explicit stack, bounded depth), ending on diffuse surfaces. Records the diffuse
// vertices to shade, the emitters seen on the way, and the first hit's AOVs.
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
#include "runtime/render/tile_order.h"
#include "runtime/shading/ray_offset.h"
#include "runtime/shading/specular.h"
#include "runtime/shading/surface_point.h"

namespace kdpm {

// The AOVs of a pixel's first hit, written by its first sample (each buffer may be null).
// `known`: the hit's surface point when the caller has it already, else null.
KDPM_HD KDPM_INLINE void write_first_hit_aovs(const GeometryView& geometry, const FrameBuffersView& frame,
                                              std::uint32_t sample, std::uint64_t pixel, const Ray& ray,
                                              const Hit& hit, const SurfacePoint* known = nullptr) {
    if (sample != 0) return;
    const bool found = hit.found();
    SurfacePoint s{};
    if (found && (frame.normal || frame.position)) s = known ? *known : surface_at(geometry, ray, hit);  // if asked for
    if (frame.depth) frame.depth[pixel] = found ? hit.t : std::numeric_limits<float>::infinity();
    if (frame.normal) frame.normal[pixel] = found ? s.geometric_normal : glm::vec3(0.0f);
    if (frame.position) frame.position[pixel] = found ? s.position : glm::vec3(0.0f);
    if (frame.triangle)
        frame.triangle[pixel] =
            found ? static_cast<std::int32_t>(object_of(geometry, hit).triangles[hit.triangle].source_index) : -1;
}

struct TracePass {
    GeometryView geometry;
    PinholeCamera camera;
    FrameBuffersView frame;
    std::uint32_t sample = 0;
    std::uint32_t max_depth = 8;
    float epsilon = 1e-4f;  // ray offset from surfaces, scaled to the scene

    struct Pending {
        glm::vec3 origin, direction, throughput;
        std::uint32_t depth;
    };
    // Mirrors and glass push at most two rays per hit; beyond kStack pending rays (deep chains
    // of glass) the further branches are dropped like rays past max_depth.
    static constexpr int kStack = 8;

    KDPM_HD void operator()(std::uint64_t item) const {
        const std::uint64_t pixel = tiled_pixel(item, frame.width, frame.height);
        trace_pixel(pixel, camera.ray_at(pixel, frame.width, sample), nullptr);
    }

    // The pixel's sample from its camera ray `cam`; `camera_hit`: that ray's closest hit when a
    // packet has traced it already (CPU, PacketTracePass), else null and traced here.
    KDPM_HD void trace_pixel(std::uint64_t pixel, const CameraRay& cam, const Hit* camera_hit) const {
        Pending stack[kStack];
        int sp = 0;
        glm::vec3 emitted(0.0f);
        std::uint32_t count = 0;
        // The camera ray first, held in registers: pushed and popped at once, its 16-byte reload
        // would straddle two 8-byte stores, which the CPU cannot forward.
        Pending r{cam.origin, cam.direction, glm::vec3(1.0f), 0u};
        for (bool first = true;; first = false) {
            if (!first) {
                if (sp == 0) break;
                r = stack[--sp];
            }
            const Ray ray{r.origin, 0.0f, r.direction, std::numeric_limits<float>::infinity()};
            const Hit hit = first && camera_hit ? *camera_hit : closest_hit(geometry, ray);
            if (!hit.found()) {
                if (first) write_aovs(pixel, ray, hit, nullptr);
                continue;
            }
            const SurfacePoint s = surface_at(geometry, ray, hit);
            if (first) write_aovs(pixel, ray, hit, &s);
            // Camera rays filter the texture over their pixel's footprint; later rays read level 0.
            const float footprint = r.depth == 0 ? uv_footprint(geometry, hit, hit.t * camera.pixel_spread()) : 0.0f;
            const MaterialRecord m = material_of(geometry, hit, footprint);
            if (s.front) emitted += r.throughput * to_vec3(m.emission);

            const glm::vec3 above = offset_origin(s.position, s.geometric_normal, epsilon, true);
            const glm::vec3 below = offset_origin(s.position, s.geometric_normal, epsilon, false);
            const bool deeper = r.depth + 1 < max_depth;
            if (m.kind == static_cast<std::uint32_t>(MaterialKind::mirror)) {
                if (deeper && sp < kStack)
                    stack[sp++] = Pending{above, reflect_dir(r.direction, s.shading_normal),
                                          r.throughput * to_vec3(m.specular), r.depth + 1};
            } else if (m.kind == static_cast<std::uint32_t>(MaterialKind::glass)) {
                glm::vec3 refracted(0.0f);
                const float f = glass_fresnel(m, r.direction, s.shading_normal, s.front, refracted);
                if (deeper && sp < kStack && f > 0.0f)
                    stack[sp++] = Pending{above, reflect_dir(r.direction, s.shading_normal), r.throughput * f,
                                          r.depth + 1};
                if (deeper && sp < kStack && f < 1.0f)
                    stack[sp++] = Pending{below, refracted, r.throughput * (1.0f - f) * to_vec3(m.transmission),
                                          r.depth + 1};
            } else if (count < kMaxDiffuseVertices) {
                frame.vertices[frame.vertex_slot(pixel, count)] =
                    DiffuseVertex{s.position, s.shading_normal, s.geometric_normal, to_vec3(m.diffuse), r.throughput};
                ++count;
            }
        }
        frame.emitted[pixel] = emitted;
        frame.vertex_count[pixel] = count;
    }

    KDPM_HD void write_aovs(std::uint64_t pixel, const Ray& ray, const Hit& hit, const SurfacePoint* s) const {
        write_first_hit_aovs(geometry, frame, sample, pixel, ray, hit, s);
    }
};

}  // namespace kdpm
