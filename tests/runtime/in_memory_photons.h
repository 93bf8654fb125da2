#pragma once
// A scene's photon maps made in-process, as kdpm-shoot-photons and kdpm-build-photons would
// make them: photons shot through the scene's geometry, the global and caustic trees, and the
// irradiance map precomputed at kdpm-build-photons' default spacing (kDefaultIrradianceEvery).
#include <cstdint>
#include <vector>

#include "builders/photons/irradiance_map_builder.h"
#include "builders/photons/photon_tree_builder.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/render/passes/photon_gather_pass.h"
#include "tests/support/built_tree_view.h"
#include "tools/photons/irradiance_step.h"

namespace kdpm::test {

struct InMemoryPhotons {
    BuiltPhotonTree global, caustic;
    BuiltIrradianceMap irradiance;

    InMemoryPhotons(const GeometryView& geometry, std::uint64_t photons, std::uint32_t bounces,
                    std::uint32_t irradiance_k) {
        ShootOptions shoot;
        shoot.photons = photons;
        shoot.max_bounces = bounces;
        const ShotPhotons shot = shoot_photons(geometry, shoot);
        global = build_photon_tree(shot.hits, PhotonTreeOptions{}, shot.info.emitted_count, bounces);
        std::vector<PhotonHit> caustic_hits;
        for (const PhotonHit& h : shot.hits)
            if (h.flags & kPhotonCaustic) caustic_hits.push_back(h);
        caustic = build_photon_tree(caustic_hits, PhotonTreeOptions{}, shot.info.emitted_count, bounces);
        const IrradiancePrecompute precompute = every_nth_photon_irradiance(kDefaultIrradianceEvery, irradiance_k);
        irradiance = build_irradiance_map(global, shot.hits, precompute(global), PhotonTreeOptions{});
    }

    // The maps as a loaded .kdp gives them; without the irradiance map when asked.
    PhotonMaps maps(bool with_irradiance = true) const {
        PhotonMaps m;
        m.global = view_of(global);
        m.caustic = view_of(caustic);
        if (with_irradiance) m.irradiance = view_of(irradiance);
        m.present = true;
        m.typical_radius = global.info.query_radius;
        return m;
    }
};

}  // namespace kdpm::test
