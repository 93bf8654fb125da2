#pragma once
// The kernels' view of a photon tree still in memory (tests), as PhotonMapFile
// gives for a mapped .kdp.
#include "builders/photons/irradiance_map_builder.h"
#include "runtime/photons/irradiance_lookup.h"
#include "tools/photons/built_photon_map_view.h"

namespace kdpm {

inline PhotonMapView view_of(const BuiltPhotonTree& t) { return photon_map_view_of(t); }

inline IrradianceMapView view_of(const BuiltIrradianceMap& m) {
    IrradianceMapView v;
    v.photons = photon_map_view_of(m.tree);
    v.irradiance = m.irradiance.data();
    return v;
}

}  // namespace kdpm
