#pragma once
// The steps of splitting one large photon node, spread over threads in fixed-size chunks and
// combined in chunk order, so that each gives exactly what its sequential version gives (and the
// tree stays the same whatever the thread count).
#include <cstdint>

#include "builders/photons/split_choice.h"
#include "builders/photons/vvh_split.h"

namespace kdpm::photon_build {

// Nodes with at least this many photons are split with these steps.
inline constexpr std::uint32_t kLargeNode = 65536;

// photon_bounds.
Cell parallel_photon_bounds(const PhotonRecord* r, std::uint32_t n);

// choose_vvh_split.
SplitChoice parallel_vvh_split(const PhotonRecord* r, std::uint32_t n, const Cell& cell, float query_radius,
                               std::uint32_t max_leaf_size, const VvhCosts& costs = {});

// std::stable_partition of r[0..n) by coordinate `axis` < `position`; returns the count below.
std::uint32_t parallel_stable_partition(PhotonRecord* r, std::uint32_t n, int axis, float position);

}  // namespace kdpm::photon_build
