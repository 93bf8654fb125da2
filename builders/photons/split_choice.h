#pragma once
// What a split strategy sees (photon positions through an index range, the node's cell) and
// what it decides (a leaf, or an axis-aligned plane). Below the plane: coordinate < position.
#include <cstdint>

namespace kdpm::photon_build {

struct Positions {
    const float* axis[3];  // coordinates indexed by hit index
};

struct Cell {
    float lo[3], hi[3];
};

struct SplitChoice {
    bool make_leaf = true;
    int axis = 0;
    float position = 0.0f;
};

// Tight bounds of the photons idx[0..n).
Cell photon_bounds(const Positions& p, const std::uint32_t* idx, std::uint32_t n);

}  // namespace kdpm::photon_build
