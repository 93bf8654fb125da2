#pragma once
// The kernels' view of a photon tree still in memory (tests), as PhotonMapFile
// gives for a mapped .kdp.
#include "tools/photons/built_photon_map_view.h"

namespace kdpm {

inline PhotonMapView view_of(const BuiltPhotonTree& t) { return photon_map_view_of(t); }

}  // namespace kdpm
