#pragma once
// A built geometry kd-tree in its file layout, and the statistics printed and recorded for it.
#include <cstdint>
#include <span>
#include <vector>

#include "builders/geometry/sah/kd_build_params.h"
#include "formats/kd_node.h"
#include "formats/triangle_clip.h"

namespace kdpm {

struct KdTreeStats {
    std::uint64_t nodes = 0;
    std::uint64_t leaves = 0;
    std::uint64_t empty_leaves = 0;
    std::uint64_t leaf_references = 0;   // total length of the leaf index array
    std::uint32_t max_depth = 0;         // inner nodes on the longest root-to-leaf path
    std::uint32_t max_leaf_triangles = 0;  // largest leaf
    double mean_leaf_triangles = 0.0;    // over non-empty leaves
    double sah_cost = 0.0;               // K_T * sum inner SA + K_I * sum leaf SA * n, over root SA
};

struct KdTree {
    AxisBox bounds{};                      // root cell: bounds of the usable triangles
    std::vector<KdNode> nodes;             // depth first, node 0 the root
    std::vector<std::uint32_t> leaf_indices;
    KdTreeStats stats;
    std::uint64_t repeated_triangles = 0;  // exact copies of an earlier triangle, left out
    KdDepthLimits limits{};                // the depth limits the build used (recorded in the file)
};

// Beyond this many triangles in one leaf (many overlapping ones that no split separates; exact
// copies are left out of the tree) every ray through the leaf tests them all: the build warns.
inline constexpr std::uint32_t kLargeLeafTriangles = 1024;

// Walks a tree in file layout and measures it (used by the builder and by tests).
KdTreeStats measure_kd_tree(std::span<const KdNode> nodes, const AxisBox& bounds, const KdBuildParams& params);

}  // namespace kdpm
