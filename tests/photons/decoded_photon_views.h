#pragma once
// A synthetic photon tree seen as the kernels may see it: with packed vectors only, with its
// vectors and powers decoded (unpack_directions, unpack_powers), and with the per-node boxes of
// those vectors as well (bound_node_vectors), as a CPU renderer keeps them.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <vector>

#include "runtime/photons/radiance_estimate.h"

#include "runtime/photons/node_vector_bounds.h"
#include "runtime/photons/unpacked_directions.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/built_tree_view.h"

namespace kdpm::test {

struct DecodedPhotonViews {
    BuiltPhotonTree tree;
    PhotonMapView packed, unpacked, bounded;
    std::vector<float> vectors, powers, bounds;
    DecodedPhotonViews(std::uint32_t photons, std::uint32_t seed)
        : tree(build_photon_tree(synthetic_photons(photons, seed).hits, PhotonTreeOptions{})),
          packed(view_of(tree)), unpacked(packed), vectors(unpack_directions(packed)), powers(unpack_powers(packed)) {
        unpacked.unpacked = vectors.data();
        unpacked.unpacked_power = powers.data();
        bounds = bound_node_vectors(unpacked);
        bounded = unpacked;
        bounded.vector_bounds = bounds.data();
    }
    // Not copyable: the views point into the members.
    DecodedPhotonViews(const DecodedPhotonViews&) = delete;
    DecodedPhotonViews& operator=(const DecodedPhotonViews&) = delete;
};

// Two estimates of the same photons: the same count, and radius and radiance bit for bit.
inline void require_same_estimate(const RadianceEstimate& a, const RadianceEstimate& b) {
    REQUIRE(a.count == b.count);
    REQUIRE(std::memcmp(&a.radius, &b.radius, sizeof a.radius) == 0);
    REQUIRE(std::memcmp(&a.radiance, &b.radiance, sizeof a.radiance) == 0);
}

}  // namespace kdpm::test
