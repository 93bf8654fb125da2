#pragma once
// A photon map's octahedral vectors and RGBE powers decoded once (PhotonMapView::unpacked and
// unpacked_power). The surface filter of a k-nearest gather decodes a photon's direction and
// surface normal at every search that meets it, and the estimate its power, dozens of times a
// photon in a frame; a CPU renderer decodes them all once instead (36 bytes a photon) and the
// gather reads them, with the very decisions and sums it made before.
#include <vector>

#include "runtime/photons/photon_map_view.h"

namespace kdpm {

// PhotonMapView::unpacked's arrays for `map`: decode_octahedral of every photon's direction, then
// of its surface normal, component by component (parallel).
std::vector<float> unpack_directions(const PhotonMapView& map);

// PhotonMapView::unpacked_power's array for `map`: photon_power of every photon (parallel).
std::vector<float> unpack_powers(const PhotonMapView& map);

}  // namespace kdpm
