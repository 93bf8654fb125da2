#pragma once
// Checks of a .kdg's geometry.wide section (format 1.2) against the kd-tree it was collapsed
// from. Structural, always: a tree from the root (each node once, children after parents, at most
// kMaxKdTreeDepth deep, so the walk's stack cannot overflow), every index in range, every box
// finite and inside its parent's, every leaf slot one kd leaf, no kd leaf the slot of two.
// Exhaustively: every leaf slot's box holds its triangles clipped to the kd leaf's cell, and a
// kd leaf without a slot holds no triangle that meets its cell.
#include <cstdint>
#include <span>

#include "formats/container_reader.h"
#include "formats/geometry_layout.h"
#include "formats/kd_node.h"
#include "formats/wide_layout.h"

namespace kdpm {

struct WideTreeArrays {
    std::span<const WideNode> wide;
    std::span<const KdNode> nodes;  // the kd-tree, already checked (check_tree)
    std::span<const std::uint32_t> leaf;
    std::span<const TriangleRecord> tris;
};

// Throws FormatError naming the file and the first failed rule.
void check_wide_tree(const ContainerReader& file, const GeometryInfo& info, const WideTreeArrays& t, bool exhaustive);

}  // namespace kdpm
