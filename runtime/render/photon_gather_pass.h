#pragma once
// Pass 2 of a frame sample: the photon-map radiance at each diffuse vertex (k-nearest photons,
// Jensen's estimate, from the photon library's KDPM_HD kernels).
//   mode photons:        every photon of the global map (direct and indirect light alike);
//   mode direct+photons: the global map without the direct hits (bounce >= 1) and without the
//                        caustic photons, plus the caustic map (direct light comes from shadow rays).
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "formats/photon_layout.h"
#include "runtime/photons/photon_map_view.h"
#include "runtime/photons/radiance_estimate.h"
#include "runtime/render/frame_buffers.h"

namespace kdpm {

// The photon maps of a .kdp (host or device arrays); empty when no photon file was given.
struct PhotonMaps {
    PhotonMapView global;
    PhotonMapView caustic;
    bool present = false;
    bool empty() const { return !present; }
};

struct PhotonGatherPass {
    FrameBuffersView frame;
    PhotonMaps maps;
    RadianceEstimateParams global_params;
    RadianceEstimateParams caustic_params;
    bool use_caustic_map = false;

    KDPM_HD void operator()(std::uint64_t slot) const {
        const std::uint64_t pixel = slot / kMaxDiffuseVertices;
        if (slot % kMaxDiffuseVertices >= frame.vertex_count[pixel]) return;
        const DiffuseVertex& v = frame.vertices[slot];
        KnnHeap heap;
        glm::vec3 l = estimate_radiance(maps.global, v.position, v.shading_normal, v.albedo, global_params, heap).radiance;
        if (use_caustic_map && maps.caustic.node_count > 0)
            l += estimate_radiance(maps.caustic, v.position, v.shading_normal, v.albedo, caustic_params, heap).radiance;
        frame.gathered[slot] = l;
    }
};

// direct_light: the mode adds direct light by shadow rays, so direct photon hits are skipped.
inline PhotonGatherPass make_gather_pass(const PhotonMaps& maps, bool direct_light, std::uint32_t k) {
    PhotonGatherPass pass;
    pass.maps = maps;
    pass.global_params.k = k < 1 ? 1 : (k > kMaxGatherK ? kMaxGatherK : k);
    pass.caustic_params = pass.global_params;
    if (direct_light) {
        pass.global_params.min_bounce = 1;
        pass.global_params.exclude_flags = kPhotonCaustic;
        pass.use_caustic_map = true;
    }
    return pass;
}

}  // namespace kdpm
