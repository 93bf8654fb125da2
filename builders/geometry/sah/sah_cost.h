#pragma once
// The surface area heuristic of one split candidate, shared by the builder and the reference
// builder in the tests so that both rank candidates with the very same arithmetic.
#include <cstdint>

#include "builders/geometry/sah/kd_build_params.h"
#include "formats/triangle_clip.h"

namespace kdpm {

inline float box_area(const AxisBox& b) {
    const float dx = b.hi[0] - b.lo[0], dy = b.hi[1] - b.lo[1], dz = b.hi[2] - b.lo[2];
    return 2.0f * (dx * dy + dy * dz + dz * dx);
}

struct SplitCost {
    float cost;
    bool planar_left;  // triangles lying in the plane go to the below side
};

// The terms of sah_split_cost that depend on the cell and the axis only: worked out once per
// axis by a sweep over many candidates (the division, inside the sweep's loop, would not be
// hoisted by the compiler). The same float expressions, so the same costs bit for bit.
struct SplitCostAxis {
    float lo, hi;     // the cell's extent on the axis
    float cap, ring;  // the cell's cross-section area and half its perimeter, across the axis
    float inv_area;   // 1 / the cell's area
};

inline SplitCostAxis split_cost_axis(const AxisBox& cell, float cell_area, int axis) {
    const int a1 = axis == 0 ? 1 : 0, a2 = axis == 2 ? 1 : 2;
    const float d1 = cell.hi[a1] - cell.lo[a1], d2 = cell.hi[a2] - cell.lo[a2];
    return SplitCostAxis{cell.lo[axis], cell.hi[axis], d1 * d2, d1 + d2, 1.0f / cell_area};
}

// Cost of a split at `pos` with nl triangles below, np in the plane and nr above; planar
// triangles go to the cheaper side (below on a tie).
inline SplitCost sah_split_cost(const KdBuildParams& p, const SplitCostAxis& a, float pos, std::uint32_t nl,
                                std::uint32_t np, std::uint32_t nr) {
    const float pl = 2.0f * (a.cap + a.ring * (pos - a.lo)) * a.inv_area;
    const float pr = 2.0f * (a.cap + a.ring * (a.hi - pos)) * a.inv_area;
    auto cost = [&](std::uint32_t l, std::uint32_t r) {
        const float c = p.traversal_cost + p.intersection_cost * (pl * static_cast<float>(l) + pr * static_cast<float>(r));
        return (l == 0 || r == 0) ? c * (1.0f - p.empty_bonus) : c;
    };
    // Without planar triangles both placements are the same split: one cost, planar_left as a tie.
    if (np == 0) return SplitCost{cost(nl, nr), true};
    const float c_left = cost(nl + np, nr), c_right = cost(nl, nr + np);
    return c_left <= c_right ? SplitCost{c_left, true} : SplitCost{c_right, false};
}

// Cost of splitting `cell` (area `cell_area` > 0) at `pos` on `axis` with nl triangles below,
// np in the plane and nr above; planar triangles go to the cheaper side (below on a tie).
inline SplitCost sah_split_cost(const KdBuildParams& p, const AxisBox& cell, float cell_area, int axis, float pos,
                                std::uint32_t nl, std::uint32_t np, std::uint32_t nr) {
    return sah_split_cost(p, split_cost_axis(cell, cell_area, axis), pos, nl, np, nr);
}

}  // namespace kdpm
