#pragma once
// One vertex of a camera path, as the path tracer, SPPM's visible-point pass and the albedo view
// follow it: the ray's closest hit, its surface point and its material. The camera ray (vertex 0)
// writes the pixel's AOVs and filters the texture over the pixel's footprint; later rays read
// the finest level.
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/render/camera.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/passes/trace_pass.h"
#include "runtime/shading/surface_point.h"
#include "runtime/shading/texture_lookup.h"

namespace kdpm {

struct PathVertex {
    Hit hit;
    SurfacePoint surface;
    MaterialRecord material;
};

// False where the ray (origin, direction) leaves the scene; else `out` is its vertex.
KDPM_HD KDPM_INLINE bool camera_path_vertex(const GeometryView& geometry, const PinholeCamera& camera,
                                            const FrameBuffersView& frame, std::uint32_t sample, std::uint64_t pixel,
                                            std::uint32_t vertex, const glm::vec3& origin, const glm::vec3& direction,
                                            PathVertex& out) {
    const Ray ray{origin, 0.0f, direction, std::numeric_limits<float>::infinity()};
    out.hit = closest_hit(geometry, ray);
    if (vertex == 0) write_first_hit_aovs(geometry, frame, sample, pixel, ray, out.hit);
    if (!out.hit.found()) return false;
    out.surface = surface_at(geometry, ray, out.hit);
    const float footprint =
        vertex == 0 ? uv_footprint(geometry, out.hit, out.hit.t * camera.pixel_spread()) : 0.0f;
    out.material = material_of(geometry, out.hit, footprint);
    return true;
}

}  // namespace kdpm
