#pragma once
// The 8-byte kd-tree node shared by the geometry tree (.kdg) and the photon tree (.kdp),
// included by builders and runtime alike. Nodes are stored depth first: an inner node's
// "below" child (coordinates < split) is the next node; its "above" child is at above_child().
#include <cstdint>
#include <cstring>

#include "formats/host_device.h"

namespace kdpm {

struct KdNode {
    // Inner node: the split plane position (a float's bits). Leaf: the first index of its items
    // (geometry: into the leaf index array; photons: into the photon arrays).
    std::uint32_t payload;
    // Bits 0-1: split axis 0..2, or 3 for a leaf. Bits 2-31: inner: index of the above child;
    // leaf: number of items.
    std::uint32_t bits;

    static constexpr std::uint32_t kLeafTag = 3u;
    static constexpr std::uint32_t kMaxIndex = (1u << 30) - 1;

    static KdNode inner(int axis, float split, std::uint32_t above_child) {
        KdNode n;
        std::memcpy(&n.payload, &split, sizeof split);
        n.bits = static_cast<std::uint32_t>(axis) | (above_child << 2);
        return n;
    }
    static KdNode leaf(std::uint32_t first, std::uint32_t count) { return KdNode{first, kLeafTag | (count << 2)}; }

    KDPM_HD bool is_leaf() const { return (bits & 3u) == kLeafTag; }
    KDPM_HD int axis() const { return static_cast<int>(bits & 3u); }
    KDPM_HD float split() const {
#if defined(__CUDA_ARCH__)
        return __uint_as_float(payload);
#else
        float f;
        std::memcpy(&f, &payload, sizeof f);
        return f;
#endif
    }
    KDPM_HD std::uint32_t above_child() const { return bits >> 2; }
    KDPM_HD std::uint32_t first() const { return payload; }
    KDPM_HD std::uint32_t count() const { return bits >> 2; }
};
static_assert(sizeof(KdNode) == 8);

}  // namespace kdpm
