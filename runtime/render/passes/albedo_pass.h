#pragma once
// --mode albedo, a debug view: the reflectance a camera ray meets first (diffuse albedo with its
// texture, a mirror's reflectance, glass's transmittance), black where it leaves the scene. No
// light at all: what a denoiser takes as its albedo guide, and a check of materials and textures.
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/render/camera.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/passes/camera_path_vertex.h"
#include "runtime/render/tile_order.h"
#include "runtime/shading/surface_point.h"
#include "runtime/shading/texture_lookup.h"

namespace kdpm {

struct AlbedoPass {
    GeometryView geometry;
    PinholeCamera camera;
    FrameBuffersView frame;
    std::uint32_t sample = 0;

    KDPM_HD void operator()(std::uint64_t item) const {
        const std::uint64_t pixel = tiled_pixel(item, frame.width, frame.height);
        const CameraRay cam = camera.ray_at(pixel, frame.width, sample);
        PathVertex at;
        if (!camera_path_vertex(geometry, camera, frame, sample, pixel, 0, cam.origin, cam.direction, at)) return;
        const MaterialRecord& m = at.material;
        const auto kind = static_cast<MaterialKind>(m.kind);
        frame.accum[pixel] += kind == MaterialKind::mirror  ? to_vec3(m.specular)
                              : kind == MaterialKind::glass ? to_vec3(m.transmission)
                                                            : to_vec3(m.diffuse);
    }
};

}  // namespace kdpm
