#pragma once
// The wide node of the .kdg's geometry.wide section (format 1.2): the SAH kd-tree collapsed into
// a tree of up to eight children per node, each child with a tight box around what its kd subtree
// holds (the triangles clipped to its cells). Empty kd leaves, most of the leaves a ray meets,
// vanish; one node replaces up to three kd levels and is tested in one 8-lane step. Leaves are
// the kd-tree's: a child leaf names its range of geometry.leaf_indices.
#include <cstdint>

namespace kdpm {

inline constexpr std::uint32_t kWideWidth = 8;
// WideNode::count of an inner child (child = index of a wide node); an empty slot has count 0.
inline constexpr std::uint32_t kWideInner = 0xffffffffu;

struct WideNode {
    // Structure of arrays, lane j = child j: box lo[axis][j] .. hi[axis][j]. An empty slot's box
    // is lo = +inf, hi = -inf, which no ray enters.
    float lo[3][kWideWidth];
    float hi[3][kWideWidth];
    std::uint32_t child[kWideWidth];  // inner: wide node index; leaf: first leaf index
    std::uint32_t count[kWideWidth];  // kWideInner, or the leaf's triangle count (0: empty slot)
};
static_assert(sizeof(WideNode) == 256);

// How many of the node's slots are used: those of count != 0 (inner or leaf); an empty slot has
// count 0.
inline std::uint32_t wide_used_slots(const WideNode& n) {
    std::uint32_t u = 0;
    for (std::uint32_t c : n.count) u += c != 0;
    return u;
}

}  // namespace kdpm
