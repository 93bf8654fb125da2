#pragma once
// The reference mode (--mode path): per pixel and sample, one camera path traced to its end in
// a single pass by path_walk.h, the camera ray's emission counted. Unbiased but for the bounce
// limits the settings ask for.
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
#include "runtime/render/passes/path_walk.h"
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
// (pixel, sample, bounce, dimension), with path_walk.h's dimensions per vertex.
struct PathPass {
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
        PathVertex first;
        if (!camera_path_vertex(geometry, camera, frame, sample, pixel, 0, cam.origin, cam.direction, first)) return;
        const PathWalk walk{geometry, lights, max_depth, max_bounces, epsilon};
        frame.accum[pixel] += walk.radiance(
            first, cam.direction, true, [&](std::uint32_t vertex) { return RandomStream{random_seed::path, path, vertex}; },
            [&](std::uint32_t vertex, const glm::vec3& origin, const glm::vec3& direction, PathVertex& out) {
                return camera_path_vertex(geometry, camera, frame, sample, pixel, vertex, origin, direction, out);
            });
    }
};

}  // namespace kdpm
