#pragma once
// Collapses a finished SAH kd-tree into the wide tree of geometry.wide (formats/wide_layout.h):
// each wide node takes the kd subtree below it down to eight non-empty parts, always opening the
// part with the largest box first (so the node's children are about equally likely to be entered),
// and boxes each part tightly around its triangles clipped to its kd cells. The kd-tree's leaves
// and leaf index array are reused as they are.
#include <cstdint>
#include <vector>

#include "formats/geometry_layout.h"
#include "formats/kd_node.h"
#include "formats/wide_layout.h"

namespace kdpm {

struct WideTreeInput {
    const KdNode* nodes;
    std::uint32_t node_count;
    const std::uint32_t* leaf_indices;
    std::uint32_t leaf_index_count;
    const TriangleRecord* triangles;
    std::uint32_t triangle_count;
    float bounds_min[3], bounds_max[3];  // the root cell
};

// The wide nodes, root first; empty for a tree without triangles in any leaf, and for a kd-tree
// that is not one (an index out of range, a node reached twice, deeper than kMaxKdTreeDepth):
// a file is then written without the wide tree and its validator names the kd-tree's fault.
std::vector<WideNode> build_wide_tree(const WideTreeInput& in);

// Margin added to every child box on each side so that float slab tests never miss a triangle
// the box holds: a millionth of the scene's extent or of its farthest coordinate, the larger.
float wide_box_margin(const float (&bounds_min)[3], const float (&bounds_max)[3]);

}  // namespace kdpm
