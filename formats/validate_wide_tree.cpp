#include "formats/validate_wide_tree.h"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "formats/format_error.h"
#include "formats/triangle_clip.h"

namespace kdpm {

namespace {

[[noreturn]] void fail(const ContainerReader& file, const std::string& why) {
    throw FormatError(file.name() + ": invalid geometry file: geometry.wide: " + why);
}

constexpr std::uint32_t kNone = 0xffffffffu;

bool slot_is_empty_box(const WideNode& n, std::uint32_t j) {
    const float inf = std::numeric_limits<float>::infinity();
    for (int a = 0; a < 3; ++a)
        if (!(n.lo[a][j] == inf && n.hi[a][j] == -inf)) return false;
    return true;
}

struct SlotRef {
    std::uint32_t node = kNone, slot = 0;
};

// Wide slot of every non-empty kd leaf, found by the structural walk (node kNone: none yet).
struct LeafSlots {
    std::vector<std::uint32_t> kd_leaf_at_first;  // kd leaf node of each first index, or kNone
    std::vector<SlotRef> slot_of_kd_leaf;         // indexed by kd node
};

LeafSlots kd_leaves(const WideTreeArrays& t) {
    LeafSlots s;
    s.kd_leaf_at_first.assign(t.leaf.size(), kNone);
    s.slot_of_kd_leaf.resize(t.nodes.size());
    for (std::uint32_t i = 0; i < t.nodes.size(); ++i)
        if (t.nodes[i].is_leaf() && t.nodes[i].count() > 0) s.kd_leaf_at_first[t.nodes[i].first()] = i;
    return s;
}

void check_structure(const ContainerReader& file, const WideTreeArrays& t, LeafSlots& leaves) {
    const std::size_t count = t.wide.size();
    std::vector<std::uint8_t> seen(count, 0);
    struct Entry {
        std::uint32_t node, depth, parent, parent_slot;
    };
    std::vector<Entry> stack{{0, 1, kNone, 0}};
    std::size_t reached = 0;
    while (!stack.empty()) {
        const Entry e = stack.back();
        stack.pop_back();
        if (seen[e.node]) fail(file, "node " + std::to_string(e.node) + " is reached twice");
        seen[e.node] = 1;
        ++reached;
        const WideNode& n = t.wide[e.node];
        const std::string which = "node " + std::to_string(e.node) + " slot ";
        for (std::uint32_t j = 0; j < kWideWidth; ++j) {
            if (n.count[j] == 0) {
                if (!slot_is_empty_box(n, j) || n.child[j] != 0)
                    fail(file, which + std::to_string(j) + " is empty but has a box or a child");
                continue;
            }
            for (int a = 0; a < 3; ++a) {
                if (!std::isfinite(n.lo[a][j]) || !std::isfinite(n.hi[a][j]) || !(n.lo[a][j] <= n.hi[a][j]))
                    fail(file, which + std::to_string(j) + " has a box that is not finite and ordered");
                if (e.parent != kNone) {
                    const WideNode& p = t.wide[e.parent];
                    if (n.lo[a][j] < p.lo[a][e.parent_slot] || n.hi[a][j] > p.hi[a][e.parent_slot])
                        fail(file, which + std::to_string(j) + " has a box outside its parent's");
                }
            }
            if (n.count[j] == kWideInner) {
                if (n.child[j] <= e.node || n.child[j] >= count)
                    fail(file, which + std::to_string(j) + " has a child index out of range");
                if (e.depth + 1 > kMaxKdTreeDepth)
                    fail(file, "tree deeper than " + std::to_string(kMaxKdTreeDepth) + " levels");
                stack.push_back({n.child[j], e.depth + 1, e.node, j});
                continue;
            }
            const std::uint32_t first = n.child[j];
            const std::uint32_t kd = first < leaves.kd_leaf_at_first.size() ? leaves.kd_leaf_at_first[first] : kNone;
            if (kd == kNone || t.nodes[kd].count() != n.count[j])
                fail(file, which + std::to_string(j) + " is not a leaf of geometry.nodes");
            if (leaves.slot_of_kd_leaf[kd].node != kNone)
                fail(file, "kd leaf " + std::to_string(kd) + " is the slot of two wide nodes");
            leaves.slot_of_kd_leaf[kd] = SlotRef{e.node, j};
        }
    }
    if (reached != count) fail(file, std::to_string(count - reached) + " nodes are not reachable from the root");
}

// Every kd leaf's triangles, clipped to its cell, inside its slot's box.
void check_boxes(const ContainerReader& file, const GeometryInfo& info, const WideTreeArrays& t,
                 const LeafSlots& leaves) {
    struct Entry {
        std::uint32_t node;
        AxisBox cell;
    };
    AxisBox root;
    for (int a = 0; a < 3; ++a) root.lo[a] = info.bounds_min[a], root.hi[a] = info.bounds_max[a];
    std::vector<Entry> stack{{0, root}};
    while (!stack.empty()) {
        const Entry e = stack.back();
        stack.pop_back();
        const KdNode& n = t.nodes[e.node];
        if (!n.is_leaf()) {
            Entry below = e, above = e;
            below.node = e.node + 1;
            below.cell.hi[n.axis()] = n.split();
            above.node = n.above_child();
            above.cell.lo[n.axis()] = n.split();
            stack.push_back(above);
            stack.push_back(below);
            continue;
        }
        if (n.count() == 0) continue;
        // A kd leaf without a slot (a fast build's leaf listing triangles that only come near
        // its cell) must hold nothing inside its cell.
        const SlotRef s = leaves.slot_of_kd_leaf[e.node];
        for (std::uint32_t i = 0; i < n.count(); ++i) {
            double v[3][3];
            triangle_vertices(t.tris[t.leaf[n.first() + i]], v);
            AxisBox clipped;
            if (!clip_triangle_to_box(v, e.cell, clipped)) continue;
            if (s.node == kNone)
                fail(file, "kd leaf " + std::to_string(e.node) + " holds triangle " +
                               std::to_string(t.leaf[n.first() + i]) + " in its cell but has no wide slot");
            const WideNode& w = t.wide[s.node];
            for (int a = 0; a < 3; ++a)
                if (clipped.lo[a] < w.lo[a][s.slot] || clipped.hi[a] > w.hi[a][s.slot])
                    fail(file, "the box of node " + std::to_string(s.node) + " slot " + std::to_string(s.slot) +
                                   " does not hold triangle " + std::to_string(t.leaf[n.first() + i]) +
                                   " of kd leaf " + std::to_string(e.node));
        }
    }
}

}  // namespace

void check_wide_tree(const ContainerReader& file, const GeometryInfo& info, const WideTreeArrays& t, bool exhaustive) {
    if (t.wide.empty()) return;
    LeafSlots leaves = kd_leaves(t);
    check_structure(file, t, leaves);
    if (exhaustive) check_boxes(file, info, t, leaves);
}

}  // namespace kdpm
