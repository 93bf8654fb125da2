#pragma once
// Builds a photon kd-tree over photon hits: the VVH tree (default) or the classic balanced
// median tree, with the photons reordered into leaf order as structure-of-arrays (positions
// x/y/z, RGBE power, octahedral direction + normal, flags). Deterministic: the result does not
// depend on the number of threads (subtrees are built independently and joined in order, and
// large nodes bin and partition their photons in fixed chunks: see large_node.h).
#include <cstdint>
#include <span>
#include <vector>

#include "formats/kd_node.h"
#include "formats/photon_layout.h"

namespace kdpm {

// Most photons in a leaf unless asked otherwise. VVH's buckets are large: its cost model
// (vvh_split.h) stops splitting long before, where a node step costs more than the photons it
// would spare a search, which the 16-wide leaf scan made cheap. The balanced tree has no cost
// to stop it, so its classic small buckets.
inline constexpr std::uint32_t kVvhLeafSize = 64;
inline constexpr std::uint32_t kBalancedLeafSize = 16;

struct PhotonTreeOptions {
    PhotonTreeBuilder builder = PhotonTreeBuilder::vvh;
    std::uint32_t leaf_size = 0;  // most photons in a leaf (VVH may stop earlier by cost); 0: the builder's
    float query_radius = 0.0f;    // VVH expected query radius; <= 0: estimated from the photons
};

// The leaf size the builder uses: the options' own, else its builder's default.
inline std::uint32_t leaf_size_of(const PhotonTreeOptions& o) {
    if (o.leaf_size > 0) return o.leaf_size;
    return o.builder == PhotonTreeBuilder::balanced ? kBalancedLeafSize : kVvhLeafSize;
}

struct BuiltPhotonTree {
    PhotonTreeInfo info{};
    std::vector<KdNode> nodes;
    std::vector<float> x, y, z;
    std::vector<std::uint32_t> power;
    std::vector<PackedPhotonDirections> directions;
    std::vector<std::uint32_t> flags;
    std::vector<std::uint32_t> source;  // slot -> index into the input hits (not written to the file)
};

// `emitted_count` and `max_bounces` are copied into the info. Throws std::invalid_argument for
// more photons than a KdNode can address.
BuiltPhotonTree build_photon_tree(std::span<const PhotonHit> hits, const PhotonTreeOptions& options,
                                  std::uint64_t emitted_count = 0, std::uint32_t max_bounces = 0);

}  // namespace kdpm
