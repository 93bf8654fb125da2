#pragma once
// Pass 3 of a frame sample: per pixel, the emitters seen plus, at each diffuse vertex, direct
// light by shadow rays (modes direct+photons and direct) and the photon-map radiance of the
// gather pass, weighted by the vertex's specular throughput; added to the pixel's sum.
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/tile_order.h"
#include "runtime/shading/direct_light.h"
#include "runtime/shading/ray_offset.h"

namespace kdpm {

struct ShadePass {
    GeometryView geometry;
    LightSelection lights;
    FrameBuffersView frame;
    std::uint32_t sample = 0;
    std::uint32_t light_samples = 16;
    bool direct = true;    // shadow rays to the lights
    bool photons = true;   // add the gathered photon radiance
    float epsilon = 1e-4f;

    KDPM_HD void operator()(std::uint64_t item) const {
        const std::uint64_t pixel = tiled_pixel(item, frame.width, frame.height);
        glm::vec3 radiance = frame.emitted[pixel];
        const std::uint32_t count = frame.vertex_count[pixel];
        for (std::uint32_t v = 0; v < count; ++v) {
            const std::uint64_t slot = frame.vertex_slot(pixel, v);
            const DiffuseVertex& d = frame.vertices[slot];
            glm::vec3 l(0.0f);
            if (direct) {
                // Offset along the geometric normal, cosine with the shading normal.
                const glm::vec3 origin = offset_origin(d.position, d.geometric_normal, epsilon, true);
                l += direct_light(geometry, lights, origin, d.shading_normal, d.albedo, light_samples,
                                  static_cast<std::uint32_t>(pixel), sample * kMaxDiffuseVertices + v);
            }
            if (photons) l += frame.gathered[slot];
            radiance += d.throughput * l;
        }
        frame.accum[pixel] += radiance;
    }
};

}  // namespace kdpm
