#include "builders/geometry/sah/kd_tree_stats.h"

#include <vector>

namespace kdpm {

using sah_detail::TreeStatsSum;

KdTreeStats measure_kd_tree(std::span<const KdNode> nodes, const AxisBox& bounds, const KdBuildParams& params) {
    if (nodes.empty()) return KdTreeStats{};
    // Depth first, below child first: node order. The below child follows at once with the cell
    // cut in place; only above children wait on the stack.
    struct Entry {
        std::uint32_t node, depth;
        AxisBox cell;
    };
    std::vector<Entry> stack;
    std::uint32_t node = 0, depth = 0;
    AxisBox cell = bounds;
    TreeStatsSum sum;
    for (;;) {
        const KdNode& n = nodes[node];
        const double area = box_area(cell);
        if (!n.is_leaf()) {
            sum.inner(area);
            Entry above{n.above_child(), depth + 1, cell};
            above.cell.lo[n.axis()] = n.split();
            stack.push_back(above);
            cell.hi[n.axis()] = n.split();
            ++node;
            ++depth;
            continue;
        }
        sum.leaf(n.count(), area, depth);
        if (stack.empty()) break;
        node = stack.back().node;
        depth = stack.back().depth;
        cell = stack.back().cell;
        stack.pop_back();
    }
    return sum.finish(nodes.size(), bounds, params);
}

}  // namespace kdpm
