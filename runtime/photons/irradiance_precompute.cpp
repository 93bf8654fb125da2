#include "runtime/photons/irradiance_precompute.h"

#include <glm/vec3.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "runtime/photons/irradiance_lookup.h"
#include "runtime/photons/node_vector_bounds.h"
#include "runtime/shading/constants.h"

namespace kdpm {

RadianceEstimateParams irradiance_estimate_params(std::uint32_t k, float typical_radius_32) {
    RadianceEstimateParams params;
    params.k = clamp_gather_k(k);
    params.max_radius = scaled_gather_radius(typical_radius_32, params.k, kIrradianceRadiusFactor);
    params.plane_distance = kPlaneDistanceFactor * typical_radius_32;
    return params;
}

std::vector<std::uint32_t> every_nth_photon(std::uint32_t photon_count, std::uint32_t every) {
    std::vector<std::uint32_t> slots;
    if (every == 0) return slots;
    for (std::uint64_t s = 0; s < photon_count; s += every) slots.push_back(static_cast<std::uint32_t>(s));
    return slots;
}

PrecomputedIrradiance irradiance_at_photon(const PhotonMapView& global, std::uint32_t slot,
                                           const RadianceEstimateParams& params, KnnHeap& heap, RadiusHints* hints) {
    const glm::vec3 position(global.x[slot], global.y[slot], global.z[slot]);
    float n[3];
    decode_octahedral(global.directions[slot].normal, n);
    // With albedo pi the estimate's f_r is 1: the radiance estimate is the irradiance.
    const glm::vec3 normal(n[0], n[1], n[2]);
    const glm::vec3 e =
        (hints ? estimate_radiance_near(global, position, normal, glm::vec3(kPi), params, heap, *hints)
               : estimate_radiance(global, position, normal, glm::vec3(kPi), params, heap))
            .radiance;
    return PrecomputedIrradiance{{e.x, e.y, e.z}};
}

std::vector<PrecomputedIrradiance> precompute_irradiance(const PhotonMapView& global,
                                                         const std::vector<std::uint32_t>& slots,
                                                         const RadianceEstimateParams& params) {
    std::vector<PrecomputedIrradiance> out(slots.size());
    if (slots.empty()) return out;
    // The photons' vectors decoded once and each node's boxes of them, as a CPU renderer keeps
    // them: a filter judges a leaf's photons 16 at a time and skips subtrees it refuses whole,
    // deciding as it would from the packed vectors (the same values, bit for bit).
    PhotonMapView map = global;
    const SearchVectors kept = map.unpacked == nullptr ? attach_search_vectors(map) : SearchVectors{};
    // Fixed groups of consecutive slots (neighbours in leaf order), each in turn so that every
    // search starts from the radii of the ones before it; fixed, so the values do not depend on
    // how the threads split the work.
    constexpr std::size_t kGroup = 64;
    const std::size_t groups = (slots.size() + kGroup - 1) / kGroup;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups, 4), [&](const tbb::blocked_range<std::size_t>& r) {
        KnnHeap heap;
        for (std::size_t g = r.begin(); g != r.end(); ++g) {
            RadiusHints hints;
            const std::size_t end = (g + 1) * kGroup < slots.size() ? (g + 1) * kGroup : slots.size();
            for (std::size_t i = g * kGroup; i != end; ++i)
                out[i] = irradiance_at_photon(map, slots[i], params, heap, &hints);
        }
    });
    return out;
}

}  // namespace kdpm
