#pragma once
// A final-gather hit's irradiance from the .kdp's irradiance map (Christensen 1999): the value
// precomputed at the nearest chosen photon whose surface agrees with the hit's (normal within
// min_normal_cos, arrived from the hit's side, and lying within a plane distance of the hit's
// tangent plane, radiance_estimate.h's plane test), one k = 1 search instead of a k-nearest
// estimate.
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "formats/photon_layout.h"
#include "runtime/photons/knn_search.h"
#include "runtime/photons/photon_map_view.h"
#include "runtime/photons/radiance_estimate.h"

namespace kdpm {

// The irradiance map as the kernels read it; photons.node_count 0 when the .kdp has none.
struct IrradianceMapView {
    PhotonMapView photons;
    const PrecomputedIrradiance* irradiance = nullptr;  // one per photon, leaf order
    KDPM_HD bool present() const { return photons.node_count > 0 && photons.photon_count > 0; }
};

// The search radius of a k-nearest estimate when it is left automatic: `factor` times the
// typical distance to the 32nd photon, scaled to k photons (same density, k / 32 the area).
KDPM_HD KDPM_INLINE float scaled_gather_radius(float typical_radius_32, std::uint32_t k, float factor) {
    return typical_radius_32 > 0.0f ? factor * typical_radius_32 * sqrtf(static_cast<float>(k) / 32.0f) : 0.0f;
}

// False when no chosen photon lies within max_radius (> 0; <= 0: unlimited) on this surface.
// max_plane_distance <= 0: no plane test.
KDPM_HD inline bool lookup_irradiance(const IrradianceMapView& map, glm::vec3 position, glm::vec3 normal,
                                      float max_radius, float min_normal_cos, float max_plane_distance, KnnHeap& heap,
                                      glm::vec3& irradiance) {
    const std::uint32_t found =
        max_plane_distance > 0.0f
            ? knn_search(map.photons, position, 1u, max_radius, EuclideanMetric{},
                         on_plane_filter(map.photons, position, normal, min_normal_cos, max_plane_distance), heap)
            : knn_search(map.photons, position, 1u, max_radius, EuclideanMetric{},
                         SurfacePhotonFilter(map.photons, normal, min_normal_cos, 0u, 0u), heap);
    if (found == 0) return false;
    const PrecomputedIrradiance& e = map.irradiance[heap.index[0]];
    irradiance = glm::vec3(e.rgb[0], e.rgb[1], e.rgb[2]);
    return true;
}

}  // namespace kdpm
