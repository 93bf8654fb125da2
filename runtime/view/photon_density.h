#pragma once
// The photon density view on host arrays (the CPU backend): at each pixel's first hit, the k
// nearest photons of the global map give an areal density estimate k / (pi r_k^2) (photons per
// square scene unit), so dark/blotchy regions show where the estimate is starved. The viewer
// goes through Renderer::photon_density, which runs the same kernel on the frame's backend.
#include <cstdint>
#include <vector>

#include "runtime/photons/photon_map_view.h"

namespace kdpm {

// positions/normals: 3 floats per pixel (the position and normal AOVs); a pixel whose normal is
// zero missed the scene and gets density 0.
std::vector<float> photon_density(const PhotonMapView& map, const std::vector<float>& positions,
                                  const std::vector<float>& normals, std::uint32_t k);

}  // namespace kdpm
