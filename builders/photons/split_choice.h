#pragma once
// What a split strategy sees (photon positions through an index range, the node's cell) and
// what it decides (a leaf, or an axis-aligned plane). Below the plane: coordinate < position.
#include <cstdint>

namespace kdpm::photon_build {

// A photon as the tree build moves it: its position beside its hit index. The build reorders
// these records themselves, not indices into the positions, so that every pass over a node
// (bounds, bins, partition) reads its photons in sequence instead of gathering them from all
// over the map.
struct PhotonRecord {
    float position[3];
    std::uint32_t index;
};

struct Cell {
    float lo[3], hi[3];
};

struct SplitChoice {
    bool make_leaf = true;
    int axis = 0;
    float position = 0.0f;
};

// Tight bounds of the photons r[0..n).
Cell photon_bounds(const PhotonRecord* r, std::uint32_t n);

}  // namespace kdpm::photon_build
