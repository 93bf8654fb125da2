#pragma once
// The kernels' view of a photon tree still in memory, as PhotonMapFile gives for a mapped .kdp:
// lets kdpm-build-photons run the runtime's estimates over the tree it has just built.
#include "builders/photons/photon_tree_builder.h"
#include "runtime/photons/photon_map_view.h"

namespace kdpm {

inline PhotonMapView photon_map_view_of(const BuiltPhotonTree& t) {
    PhotonMapView v;
    v.nodes = t.nodes.data();
    v.node_count = static_cast<std::uint32_t>(t.nodes.size());
    v.photon_count = t.info.photon_count;
    v.x = t.x.data();
    v.y = t.y.data();
    v.z = t.z.data();
    v.power = t.power.data();
    v.directions = t.directions.data();
    v.flags = t.flags.data();
    v.emitted_count = t.info.emitted_count;
    return v;
}

}  // namespace kdpm
