#pragma once
// The expected gather radius the VVH cost needs when the user gives none: the median distance
// to the k-th nearest photon over a fixed sample, scaled from the sample's density to the full
// set's as for photons on surfaces (radius ~ 1 / sqrt(count)). Deterministic.
#include <cstdint>

#include "builders/photons/split_choice.h"

namespace kdpm::photon_build {

float estimate_query_radius(const PhotonRecord* photons, std::uint32_t count, std::uint32_t k = 32);

}  // namespace kdpm::photon_build
