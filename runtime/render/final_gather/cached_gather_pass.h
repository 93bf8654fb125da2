#pragma once
// Pass 2 of final gathering with the irradiance cache: at each diffuse vertex, the caustics from
// the caustic map plus albedo / pi times the irradiance interpolated from the cache's records.
// The host makes records first wherever none is valid (irradiance_cache.h), so every vertex
// finds one; should none be valid the vertex gathers itself, as without the cache.
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/render/final_gather/final_gather_pass.h"
#include "runtime/render/final_gather/irradiance_record_tree.h"

namespace kdpm {

struct CachedGatherPass {
    FinalGatherPass gather;
    IrradianceTreeView cache;

    KDPM_HD void operator()(std::uint64_t item) const {
        const FrameBuffersView& frame = gather.frame;
        const std::uint64_t pixel = tiled_pixel(item, frame.width, frame.height);
        const std::uint32_t count = frame.vertex_count[pixel];
        KnnHeap heap;
        for (std::uint32_t i = 0; i < count && i < kMaxDiffuseVertices; ++i) {
            const std::uint64_t slot = frame.vertex_slot(pixel, i);
            const DiffuseVertex& v = frame.vertices[slot];
            glm::vec3 irradiance(0.0f);
            if (!cache.interpolate(v.position, v.geometric_normal, irradiance)) {
                gather.gather_vertex(pixel, i, heap);
                continue;
            }
            glm::vec3 l = lambert_brdf(v.albedo) * irradiance;
            if (gather.maps.caustic.node_count > 0)
                l += estimate_radiance(gather.maps.caustic, v.position, v.shading_normal, v.albedo,
                                       gather.caustic_params, heap)
                         .radiance;
            frame.gathered[slot] = l;
        }
    }
};

}  // namespace kdpm
