#pragma once
// kdpm-build-photons' irradiance step: the builder's IrradiancePrecompute made from the
// runtime's estimate, over every `every`-th photon of the global map it has just built.
#include <cstdint>

#include "builders/photons/irradiance_map_builder.h"
#include "runtime/photons/irradiance_precompute.h"
#include "tools/photons/built_photon_map_view.h"

namespace kdpm {

// kdpm-build-photons' defaults for --irradiance-every and --irradiance-k.
inline constexpr std::uint32_t kDefaultIrradianceEvery = 4;
inline constexpr std::uint32_t kDefaultIrradianceK = 64;

inline IrradiancePrecompute every_nth_photon_irradiance(std::uint32_t every, std::uint32_t k) {
    return [every, k](const BuiltPhotonTree& global) {
        IrradianceSamples samples;
        samples.slots = every_nth_photon(global.info.photon_count, every);
        samples.irradiance = precompute_irradiance(photon_map_view_of(global), samples.slots,
                                                   irradiance_estimate_params(k, global.info.query_radius));
        return samples;
    };
}

// The irradiance step kdpm-build-photons runs by default, for the benchmarks that write .kdp files
// as it does.
inline IrradiancePrecompute default_photon_irradiance() {
    return every_nth_photon_irradiance(kDefaultIrradianceEvery, kDefaultIrradianceK);
}

}  // namespace kdpm
