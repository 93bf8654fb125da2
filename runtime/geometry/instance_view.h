#pragma once
// The runtime form of a scene's instances (formats/instance_layout.h): each placement with its
// inverse, and a BVH over their world boxes that the loader builds (instance_bvh.h) and rebuilds
// whenever placements change.
#include <cstdint>

#include "formats/affine_map.h"

namespace kdpm {

struct InstancePlacement {
    Affine world_from_object;
    Affine object_from_world;
    std::uint32_t object;  // index into GeometryView::objects
    std::uint32_t reserved[3];
};
static_assert(sizeof(InstancePlacement) == 112);

// A node of the instance BVH: count 0 is an inner node with children `first` and `first + 1`;
// count 1 is a leaf holding instance `first`.
struct InstanceNode {
    float lo[3];
    std::uint32_t first;
    float hi[3];
    std::uint32_t count;
};
static_assert(sizeof(InstanceNode) == 32);

// Depth of the BVH the builder makes at most (its SAH splits give way to median splits below
// depth 64, and a median split halves the count): the walk's stack bound.
inline constexpr std::uint32_t kMaxInstanceBvhDepth = 96;

}  // namespace kdpm
