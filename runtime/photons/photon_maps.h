#pragma once
// The photon maps of a .kdp as the renderer's passes read them (host or device arrays): the
// global and caustic maps and the precomputed irradiance; empty when no photon file was given.
#include "runtime/photons/irradiance_lookup.h"
#include "runtime/photons/photon_map_view.h"

namespace kdpm {

struct PhotonMaps {
    PhotonMapView global;
    PhotonMapView caustic;
    IrradianceMapView irradiance;  // the .kdp's precomputed irradiance (final gathering); may be absent
    bool present = false;
    float typical_radius = 0.0f;  // median distance to the 32nd nearest photon (.kdp info); 0: unknown
    bool empty() const { return !present; }
};

}  // namespace kdpm
