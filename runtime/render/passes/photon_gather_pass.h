#pragma once
// Pass 2 of a frame sample: the photon-map radiance at each diffuse vertex (k-nearest photons,
// Jensen's estimate, from the photon library's KDPM_HD kernels).
//   mode photons:        every photon of the global map (direct and indirect light alike);
//   mode direct+photons: the global map without the direct hits (bounce >= 1) and without the
//                        caustic photons, plus the caustic map (direct light comes from shadow rays).
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "formats/photon_layout.h"
#include "runtime/photons/irradiance_lookup.h"
#include "runtime/photons/photon_map_view.h"
#include "runtime/photons/photon_maps.h"
#include "runtime/photons/radiance_estimate.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/render_settings.h"
#include "runtime/render/tile_order.h"

namespace kdpm {

struct PhotonGatherPass {
    FrameBuffersView frame;
    PhotonMaps maps;
    RadianceEstimateParams global_params;
    RadianceEstimateParams caustic_params;
    bool use_caustic_map = false;

    // One work item per pixel (tiled order), looping over the pixel's diffuse vertices: most
    // pixels have one, so launching per vertex slot would mostly start items that do nothing.
    KDPM_HD void operator()(std::uint64_t item) const {
        KnnHeap heap;
        gather_pixel(tiled_pixel(item, frame.width, frame.height), heap,
                     [](const PhotonMapView& map, bool, const DiffuseVertex& v, std::uint32_t,
                        const RadianceEstimateParams& params, KnnHeap& h) {
                         return estimate_radiance(map, v.position, v.shading_normal, v.albedo, params, h).radiance;
                     });
    }

    // The gathered radiance of each of the pixel's diffuse vertices; estimate(map, caustic?,
    // vertex, vertex index, params, heap) -> radiance (PhotonTileGatherPass searches its own way).
    template <class Estimate>
    KDPM_HD void gather_pixel(std::uint64_t pixel, KnnHeap& heap, const Estimate& estimate) const {
        const std::uint32_t count = frame.vertex_count[pixel];
        for (std::uint32_t i = 0; i < count && i < kMaxDiffuseVertices; ++i) {
            const std::uint64_t slot = frame.vertex_slot(pixel, i);
            const DiffuseVertex& v = frame.vertices[slot];
            glm::vec3 l = estimate(maps.global, false, v, i, global_params, heap);
            if (use_caustic_map && maps.caustic.node_count > 0)
                l += estimate(maps.caustic, true, v, i, caustic_params, heap);
            frame.gathered[slot] = l;
        }
    }
};

// Default search limit: this many times the typical radius for k photons. Where photons are
// sparse (dark corners, or the indirect-only subset), an unlimited k-nearest search wanders
// over much of the scene; beyond the limit the estimate uses the photons found in the disc.
inline constexpr float kAutoRadiusFactor = 4.0f;

// direct_light: the mode adds direct light by shadow rays, so direct photon hits are skipped.
// From the settings: k, max_radius (< 0: automatic, see kAutoRadiusFactor; 0: unlimited), and
// RadianceEstimateParams' cone_filter, flatten (disc_flatten) and fixed_radius. A fixed radius
// left automatic is the typical radius of k photons; its callers check that there is one.
inline PhotonGatherPass make_gather_pass(const PhotonMaps& maps, bool direct_light, const RenderSettings& settings) {
    PhotonGatherPass pass;
    pass.maps = maps;
    const std::uint32_t k = settings.k;
    pass.global_params.k = clamp_gather_k(k);
    pass.global_params.cone_filter = settings.cone_filter;
    pass.global_params.flatten = settings.disc_flatten > 0.0f ? settings.disc_flatten : 0.0f;
    pass.global_params.fixed_radius = settings.fixed_radius;
    float max_radius = settings.max_radius;
    if (max_radius < 0.0f && settings.fixed_radius)
        max_radius = scaled_gather_radius(maps.typical_radius, pass.global_params.k, 1.0f);
    else if (max_radius < 0.0f)
        max_radius = scaled_gather_radius(maps.typical_radius, pass.global_params.k, kAutoRadiusFactor);
    pass.global_params.max_radius = max_radius;
    pass.caustic_params = pass.global_params;
    if (direct_light) {
        pass.global_params.min_bounce = 1;
        pass.global_params.exclude_flags = kPhotonCaustic;
        pass.use_caustic_map = true;
    }
    return pass;
}

}  // namespace kdpm
