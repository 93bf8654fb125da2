#pragma once
// Per photon-tree node, the box of its photons' decoded directions and of their surface normals,
// and what their flags share (PhotonMapView::vector_bounds). A surface filter that no vector in a
// box can pass, or whose bounce and flag rules every photon fails, rules out every photon below
// that node at once: at corners and thin walls many of the leaves a k-nearest search reaches
// hold no photon its filter accepts, and a subtree ruled out is not walked. Computed from
// PhotonMapView::unpacked, once per renderer.
#include <cstdint>
#include <vector>

#include "runtime/photons/photon_map_view.h"

namespace kdpm {

// Floats per node in PhotonMapView::vector_bounds: direction min x, y, z, then the greatest
// bounce below the node (-1 for none); direction max x, y, z, then the bits every photon below
// it has set in its flags (kPhotonKnownFlags, as a float); normal min x, y, z, 0; normal max x,
// y, z, 0. Four SIMD lanes each; the fourth lanes are finite and meet a zero lane of the normal.
inline constexpr std::uint32_t kVectorBoundFloats = 16;
inline constexpr std::uint32_t kMaxBounceAt = 3, kCommonFlagsAt = 7;

// vector_bounds' array for `map`, whose `unpacked` vectors must be set (empty for an empty map).
// An empty leaf's box is empty (min > max); a NaN vector makes its nodes' boxes unbounded, so no
// test can rule them out.
std::vector<float> bound_node_vectors(const PhotonMapView& map);

// A map's decoded vectors (unpack_directions) and its node boxes, kept for its searches.
struct SearchVectors {
    std::vector<float> vectors, bounds;
};

// Decodes `map`'s vectors and bounds its nodes, and points map.unpacked and map.vector_bounds at
// the result, which must outlive the view's use (both stay null for a map without photons).
SearchVectors attach_search_vectors(PhotonMapView& map);

}  // namespace kdpm
