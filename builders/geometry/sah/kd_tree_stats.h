#pragma once
// The sums behind KdTreeStats, shared by the builder (over the pieces it built) and
// measure_kd_tree (over a finished tree).
#include <algorithm>
#include <cstdint>

#include "builders/geometry/sah/kd_build_params.h"
#include "builders/geometry/sah/kd_tree.h"
#include "builders/geometry/sah/sah_cost.h"
#include "formats/triangle_clip.h"

namespace kdpm::sah_detail {

// The sums behind KdTreeStats, taken node by node in node order (depth first, below child
// first): measure_kd_tree walks a finished tree, the builder reads the areas its pieces kept,
// and both add the same doubles in the same order, so the cost has the same bits.
class TreeStatsSum {
public:
    void inner(double area) { inner_area_ += area; }
    void leaf(std::uint32_t count, double area, std::uint32_t depth) {
        ++s_.leaves;
        s_.leaf_references += count;
        s_.max_leaf_triangles = std::max(s_.max_leaf_triangles, count);
        if (count == 0) ++s_.empty_leaves;
        else ++nonempty_;
        s_.max_depth = std::max(s_.max_depth, depth);
        leaf_area_weighted_ += area * count;
    }
    KdTreeStats finish(std::uint64_t nodes, const AxisBox& bounds, const KdBuildParams& params) {
        s_.nodes = nodes;
        const double root_area = box_area(bounds) > 0.0f ? box_area(bounds) : 1.0;
        s_.mean_leaf_triangles =
            nonempty_ ? static_cast<double>(s_.leaf_references) / static_cast<double>(nonempty_) : 0.0;
        s_.sah_cost = (params.traversal_cost * inner_area_ + params.intersection_cost * leaf_area_weighted_) / root_area;
        return s_;
    }

private:
    KdTreeStats s_;
    double inner_area_ = 0.0, leaf_area_weighted_ = 0.0;
    std::uint64_t nonempty_ = 0;
};

}  // namespace kdpm::sah_detail
