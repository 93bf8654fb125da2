#pragma once
// A photon map's octahedral vectors decoded once (PhotonMapView::unpacked). The surface filter
// of a k-nearest gather decodes a photon's direction and surface normal at every search that
// meets it, dozens of times a photon in a frame; a CPU renderer decodes them all once instead
// (24 bytes a photon) and the filter reads them, with the very decisions it took before.
#include <vector>

#include "runtime/photons/photon_map_view.h"

namespace kdpm {

// PhotonMapView::unpacked's arrays for `map`: decode_octahedral of every photon's direction, then
// of its surface normal, component by component (parallel).
std::vector<float> unpack_directions(const PhotonMapView& map);

}  // namespace kdpm
