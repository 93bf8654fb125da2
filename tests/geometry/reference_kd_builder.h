#pragma once
// A straightforward O(N^2) SAH kd-tree builder for tests: at each node every clipped triangle
// bound is a candidate and the triangles on each side are counted by looping over all of them.
// Same candidates, cost function, tie rules and perfect-split clipping as the real builder, so
// both must reach the same tree and SAH cost.
#include <cstring>
#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "builders/geometry/sah/kd_tree.h"
#include "builders/geometry/sah/sah_cost.h"
#include "formats/triangle_clip.h"

namespace kdpm::test {

class ReferenceKdBuilder {
public:
    ReferenceKdBuilder(std::span<const TriangleRecord> tris, const KdBuildParams& params)
        : tris_(tris), params_(params) {}

    KdTree build() {
        std::vector<std::uint32_t> ids;
        // Usable triangles that are not an exact copy of an earlier one (compared pairwise here).
        auto same = [](const TriangleRecord& a, const TriangleRecord& b) {
            return std::memcmp(a.v0, b.v0, sizeof a.v0) == 0 && std::memcmp(a.e1, b.e1, sizeof a.e1) == 0 &&
                   std::memcmp(a.e2, b.e2, sizeof a.e2) == 0;
        };
        for (std::uint32_t i = 0; i < tris_.size(); ++i) {
            if (!triangle_is_usable(tris_[i])) continue;
            bool copy = false;
            for (std::uint32_t j : ids) copy = copy || same(tris_[i], tris_[j]);
            if (!copy) ids.push_back(i);
        }
        limits_ = KdDepthLimits::of(params_, ids.size());
        AxisBox bounds{{0, 0, 0}, {0, 0, 0}};
        if (!ids.empty()) {
            for (int a = 0; a < 3; ++a) bounds.lo[a] = INFINITY, bounds.hi[a] = -INFINITY;
            for (std::uint32_t g : ids) {
                const AxisBox b = triangle_bounds(tris_[g]);
                for (int a = 0; a < 3; ++a) bounds.lo[a] = std::min(bounds.lo[a], b.lo[a]), bounds.hi[a] = std::max(bounds.hi[a], b.hi[a]);
            }
        }
        std::vector<std::uint32_t> kept;
        std::vector<AxisBox> boxes;
        for (std::uint32_t g : ids) {
            AxisBox b;
            if (clip(g, bounds, b)) kept.push_back(g), boxes.push_back(b);
        }
        KdTree tree;
        tree.bounds = bounds;
        node(kept, boxes, bounds, 0, tree);
        tree.stats = measure_kd_tree(tree.nodes, bounds, params_);
        return tree;
    }

private:
    bool clip(std::uint32_t g, const AxisBox& cell, AxisBox& out) const {
        double v[3][3];
        triangle_vertices(tris_[g], v);
        return clip_triangle_to_box(v, cell, out);
    }

    void node(const std::vector<std::uint32_t>& ids, const std::vector<AxisBox>& boxes, const AxisBox& cell,
              std::uint32_t depth, KdTree& tree) {
        const std::uint32_t n = static_cast<std::uint32_t>(ids.size());
        int best_axis = -1;
        float best_pos = 0.0f;
        bool best_planar_left = true;
        const float area = box_area(cell);
        if (n > 0 && n > static_cast<std::uint32_t>(params_.leaf_size) && limits_.may_split(depth, n) && area > 0.0f) {
            float best_cost = params_.intersection_cost * static_cast<float>(n);
            for (int k = 0; k < 3; ++k) {
                if (!(cell.hi[k] > cell.lo[k])) continue;
                std::vector<float> candidates;
                for (const AxisBox& b : boxes) candidates.push_back(b.lo[k]), candidates.push_back(b.hi[k]);
                std::sort(candidates.begin(), candidates.end());
                candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
                for (float p : candidates) {
                    if (!(p > cell.lo[k] && p < cell.hi[k])) continue;
                    std::uint32_t nl = 0, np = 0, nr = 0;
                    for (const AxisBox& b : boxes) {
                        if (b.lo[k] == b.hi[k]) {
                            nl += b.lo[k] < p;
                            np += b.lo[k] == p;
                            nr += b.lo[k] > p;
                        } else {
                            nl += b.lo[k] < p;
                            nr += b.hi[k] > p;
                        }
                    }
                    const SplitCost c = sah_split_cost(params_, cell, area, k, p, nl, np, nr);
                    if (c.cost < best_cost) best_cost = c.cost, best_axis = k, best_pos = p, best_planar_left = c.planar_left;
                }
            }
        }
        if (best_axis < 0) {
            tree.nodes.push_back(KdNode::leaf(static_cast<std::uint32_t>(tree.leaf_indices.size()), n));
            tree.leaf_indices.insert(tree.leaf_indices.end(), ids.begin(), ids.end());
            return;
        }
        const int k = best_axis;
        const float p = best_pos;
        AxisBox lcell = cell, rcell = cell;
        lcell.hi[k] = p;
        rcell.lo[k] = p;
        std::vector<std::uint32_t> lids, rids;
        std::vector<AxisBox> lboxes, rboxes;
        for (std::size_t i = 0; i < ids.size(); ++i) {
            const AxisBox& b = boxes[i];
            bool left, right;
            if (b.lo[k] == b.hi[k]) {
                left = b.lo[k] < p || (b.lo[k] == p && best_planar_left);
                right = !left;
            } else {
                left = b.lo[k] < p;
                right = b.hi[k] > p;
            }
            if (left && right) {
                AxisBox c;
                if (clip(ids[i], lcell, c)) lids.push_back(ids[i]), lboxes.push_back(c);
                if (clip(ids[i], rcell, c)) rids.push_back(ids[i]), rboxes.push_back(c);
            } else if (left) {
                lids.push_back(ids[i]), lboxes.push_back(b);
            } else {
                rids.push_back(ids[i]), rboxes.push_back(b);
            }
        }
        const std::size_t index = tree.nodes.size();
        tree.nodes.push_back(KdNode{});
        node(lids, lboxes, lcell, depth + 1, tree);
        tree.nodes[index] = KdNode::inner(k, p, static_cast<std::uint32_t>(tree.nodes.size()));
        node(rids, rboxes, rcell, depth + 1, tree);
    }

    std::span<const TriangleRecord> tris_;
    KdBuildParams params_;
    KdDepthLimits limits_{};
};

}  // namespace kdpm::test
