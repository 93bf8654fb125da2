#pragma once
// The instance BVH: binned SAH over the instances' world boxes, one instance a leaf. Built by the
// loader in O(n log n) (10^4 instances in a few milliseconds), cheap enough to rebuild whenever
// instances move.
#include <cstdint>
#include <span>
#include <vector>

#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/instance_view.h"

namespace kdpm {

struct WorldBox {
    float lo[3];
    float hi[3];
};

// The world box of an object's bounds under a map: its eight corners mapped, boxed.
WorldBox placed_bounds(const GeometryInfo& object, const Affine& world_from_object);

// Nodes in depth-first order, node 0 the root; empty for no boxes. Depth <= kMaxInstanceBvhDepth.
std::vector<InstanceNode> build_instance_bvh(std::span<const WorldBox> boxes);

}  // namespace kdpm
