#pragma once
// The voxel volume heuristic (Wald, Günther, Slusallek 2004, "Balancing considered harmful"):
// a query of radius r touches a cell with a probability proportional to the volume of the cell
// grown by r on every side, so a split costs
//   C_traverse + sum over children of  V_r(child) / V_r(cell) * N_child * C_photon
// and a node stays a leaf (a bucket of photons) when that is not cheaper than N * C_photon.
// Candidates: binned planes inside the photons' bounds, plus planes that cut empty space off
// the cell on either side.
#include "builders/photons/split_choice.h"

namespace kdpm::photon_build {

struct VvhCosts {
    // An inner node step with its stack push and pop costs many photon distance tests because a
    // leaf is scanned 16 photons at a time; 16 (with leaves of up to 64) gives the fastest gathers.
    float traverse = 16.0f;
    float photon = 1.0f;    // one photon distance test
};

// Leaf when n <= 1, or when n <= max_leaf_size and no split is cheaper; above max_leaf_size
// the cheapest split is taken anyway (leaf only when all photons coincide).
SplitChoice choose_vvh_split(const PhotonRecord* r, std::uint32_t n, const Cell& cell,
                             float query_radius, std::uint32_t max_leaf_size, const VvhCosts& costs = {});

// choose_vvh_split in two steps, so that a large node can count its photons in parallel chunks:
// the photons' bounds `b` (photon_bounds) and their counts in kVvhBins bins per axis over b.
inline constexpr int kVvhBins = 32;
using VvhBins = std::uint32_t[3][kVvhBins];

// Adds the photons r[0..n) to `counts` (axes where b is flat are left alone).
void count_vvh_bins(const PhotonRecord* r, std::uint32_t n, const Cell& b, VvhBins& counts);

SplitChoice choose_vvh_split_from_bins(const Cell& b, const VvhBins& counts, std::uint32_t n, const Cell& cell,
                                       float query_radius, std::uint32_t max_leaf_size, const VvhCosts& costs = {});

}  // namespace kdpm::photon_build
