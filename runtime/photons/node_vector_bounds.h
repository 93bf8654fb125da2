#pragma once
// Per photon-tree node, the box of its photons' decoded directions and of their surface normals
// (PhotonMapView::vector_bounds). A surface filter that no vector in a box can pass rules out
// every photon below that node at once: at corners and thin walls about half the leaves a
// Sponza k-nearest search reaches hold no photon its filter accepts (a fifth to a half on the
// shared scenes), and a subtree ruled out is not walked. Computed from PhotonMapView::unpacked,
// once per renderer.
#include <cstdint>
#include <vector>

#include "runtime/photons/photon_map_view.h"

namespace kdpm {

// Floats per node in PhotonMapView::vector_bounds: direction min x, y, z, 0; direction max x, y,
// z, 0; normal min; normal max (four SIMD lanes each, the fourth always 0).
inline constexpr std::uint32_t kVectorBoundFloats = 16;

// vector_bounds' array for `map`, whose `unpacked` vectors must be set (empty for an empty map).
// An empty leaf's box is empty (min > max); a NaN vector makes its nodes' boxes unbounded, so no
// test can rule them out.
std::vector<float> bound_node_vectors(const PhotonMapView& map);

}  // namespace kdpm
