#pragma once
// O(N log N) SAH kd-tree build after Wald & Havran, "On building fast kd-trees for ray tracing,
// and on doing that in O(N log N)" (2006): split events are sorted once and kept sorted while
// splitting, candidates are the bounds of triangles clipped to the node cell (perfect splits),
// planar triangles go to the cheaper side, empty space gets a bonus, and a node becomes a leaf
// when no split is cheaper than intersecting all its triangles.
//
// Subtrees of large nodes are built in parallel (oneTBB) and assembled depth first in a fixed
// order, so the result is identical whatever the number of threads.
#include <functional>
#include <span>

#include "builders/geometry/sah/kd_build_params.h"
#include "builders/geometry/sah/kd_tree.h"
#include "formats/geometry_layout.h"

namespace kdpm {

// Triangles that are not usable (zero area, non-finite) or repeat an earlier one exactly
// (repeated_triangles.h) are left out of the tree; the others keep their index. `progress` (optional) receives a rough fraction done, from any thread.
KdTree build_sah_kd_tree(std::span<const TriangleRecord> triangles, const KdBuildParams& params,
                         const std::function<void(double)>& progress = {});

}  // namespace kdpm
