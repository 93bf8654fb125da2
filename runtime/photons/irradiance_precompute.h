#pragma once
// The irradiance stored in a .kdp's irradiance map: at every `every`-th photon of the global map
// (leaf order, so the chosen ones spread like the photons), the k-nearest density estimate of
// the runtime (estimate_radiance over every photon of the map, direct and caustic ones
// included, with the plane test) at the photon's position and stored normal, as irradiance
// E = pi * L / albedo.
#include <cstdint>
#include <vector>

#include "formats/photon_layout.h"
#include "runtime/photons/photon_map_view.h"
#include "runtime/photons/radiance_estimate.h"

namespace kdpm {

// The search limit of the precomputation: the renderer's automatic one (kAutoRadiusFactor
// times the typical radius for k photons), so the stored value is what a gather would compute.
inline constexpr float kIrradianceRadiusFactor = 4.0f;

// The estimate's parameters for k photons, from the map's typical 32nd-photon radius (.kdp info
// query_radius; 0: unlimited search).
RadianceEstimateParams irradiance_estimate_params(std::uint32_t k, float typical_radius_32);

// Slots 0, every, 2 every, ... below photon_count (every >= 1).
std::vector<std::uint32_t> every_nth_photon(std::uint32_t photon_count, std::uint32_t every);

// The irradiance at each slot of `global` (parallel; the result does not depend on the threads).
std::vector<PrecomputedIrradiance> precompute_irradiance(const PhotonMapView& global,
                                                         const std::vector<std::uint32_t>& slots,
                                                         const RadianceEstimateParams& params);

// One photon's value, as precompute_irradiance computes it. hints: the radii of the searches just
// made nearby (the search starts from them); may be null, and does not change which photons are
// found.
PrecomputedIrradiance irradiance_at_photon(const PhotonMapView& global, std::uint32_t slot,
                                           const RadianceEstimateParams& params, KnnHeap& heap,
                                           RadiusHints* hints = nullptr);

}  // namespace kdpm
