#pragma once
// The optional irradiance map of a .kdp (Christensen 1999): a photon kd-tree over a subset of
// the global map's photons, each with the irradiance precomputed at it, so a final-gather hit
// reads one nearest photon instead of making a k-nearest estimate. The builder only arranges
// what it is given: the estimates themselves come from the runtime's kernels (the caller's
// IrradiancePrecompute), which the builders do not link.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "builders/photons/photon_tree_builder.h"
#include "formats/container_writer.h"
#include "formats/photon_layout.h"

namespace kdpm {

struct IrradianceSamples {
    std::vector<std::uint32_t> slots;               // global-map photons (leaf order), strictly ascending
    std::vector<PrecomputedIrradiance> irradiance;  // one per slot
};

// Given the built global map, the photons to keep and their irradiance.
using IrradiancePrecompute = std::function<IrradianceSamples(const BuiltPhotonTree& global)>;

struct BuiltIrradianceMap {
    BuiltPhotonTree tree;                           // over the chosen photons, in its own leaf order
    std::vector<PrecomputedIrradiance> irradiance;  // per photon of `tree`
    std::vector<std::uint32_t> global_slot;         // per photon of `tree`: its slot in the global map
};

// `hits` are the photons the global tree was built from. Throws std::invalid_argument when the
// samples do not match the global map (sizes, slots out of range or not ascending).
BuiltIrradianceMap build_irradiance_map(const BuiltPhotonTree& global, std::span<const PhotonHit> hits,
                                        const IrradianceSamples& samples, const PhotonTreeOptions& options);

void add_irradiance_map_sections(ContainerWriter& writer, const BuiltIrradianceMap& map);

}  // namespace kdpm
