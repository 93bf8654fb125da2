#pragma once
// The classic balanced photon map split (Jensen): the median along the widest axis of the
// photons' bounds, so both halves hold about the same number of photons.
#include "builders/photons/split_choice.h"

namespace kdpm::photon_build {

// May reorder r[0..n) (a selection). Leaf when n <= leaf_size or all photons coincide.
SplitChoice choose_median_split(PhotonRecord* r, std::uint32_t n, std::uint32_t leaf_size);

}  // namespace kdpm::photon_build
