#include "runtime/render/final_gather/irradiance_record_tree.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace kdpm {

namespace {
constexpr std::uint32_t kLeafRecords = 4;
}

void IrradianceRecordTree::add(const std::vector<IrradianceRecord>& records) {
    const auto first = static_cast<std::uint32_t>(records_.size());
    records_.insert(records_.end(), records.begin(), records.end());
    rebuild();
    if (records.empty()) return;
    // In index order, so the radii do not depend on the thread count.
    for (auto j = first; j < records_.size(); ++j) clamp_by_neighbours(j);
    refit(0);  // the spheres have shrunk; the positions, and so the tree's shape, are the same
}

void IrradianceRecordTree::rebuild() {
    order_.resize(records_.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    nodes_.clear();
    if (!records_.empty()) build(0, static_cast<std::uint32_t>(order_.size()), 0);
}

// Every record i that clamps j or that j clamps: R_i > R_j + d puts p_j inside i's R-sphere, so
// inside the R-sphere bounds of every node above i; R_j > R_i + d puts p_i within R_j of p_j, so
// the valid-sphere bounds (which hold the positions) of those nodes within R_j. Asking the two
// apart, and not whether the R-sphere bounds meet the ball of radius R_j, skips the nodes whose
// R-spheres only come near p_j: in an open room records have the 3 m cap, and the wider test met
// nearly every node (9 % of a Sponza final-gather frame, on one thread).
void IrradianceRecordTree::clamp_by_neighbours(std::uint32_t j) {
    stack_.assign(1, 0u);
    while (!stack_.empty()) {
        const auto self = stack_.back();
        const IrradianceTreeNode& node = nodes_[self];
        stack_.pop_back();
        IrradianceRecord& rj = records_[j];
        const bool in_spheres = glm::all(glm::greaterThanEqual(rj.position, node.sphere_lo)) &&
                                glm::all(glm::lessThanEqual(rj.position, node.sphere_hi));
        if (!in_spheres) {
            const glm::vec3 gap = glm::clamp(rj.position, node.lo, node.hi) - rj.position;
            if (glm::dot(gap, gap) > rj.radius * rj.radius) continue;
        }
        if (node.count == 0) {
            stack_.push_back(node.first);
            stack_.push_back(self + 1);
            continue;
        }
        for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
            const std::uint32_t i = order_[k];
            if (i == j) continue;
            IrradianceRecord& ri = records_[i];
            const float d = glm::length(ri.position - rj.position);
            if (ri.radius > rj.radius + d) ri.radius = rj.radius + d;
            if (rj.radius > ri.radius + d) rj.radius = ri.radius + d;
        }
    }
}

// The node's bounds of the valid spheres and of the R-spheres of records order_[begin, end).
void IrradianceRecordTree::bound(IrradianceTreeNode& node, std::uint32_t begin, std::uint32_t end) const {
    node.lo = node.sphere_lo = glm::vec3(1e30f);
    node.hi = node.sphere_hi = glm::vec3(-1e30f);
    for (std::uint32_t i = begin; i < end; ++i) {
        const IrradianceRecord& r = records_[order_[i]];
        const glm::vec3 reach(accuracy_ * r.radius);
        node.lo = glm::min(node.lo, r.position - reach);
        node.hi = glm::max(node.hi, r.position + reach);
        node.sphere_lo = glm::min(node.sphere_lo, r.position - glm::vec3(r.radius));
        node.sphere_hi = glm::max(node.sphere_hi, r.position + glm::vec3(r.radius));
    }
}

// The bounds again after the radii changed: the leaves' from their records, an inner node's
// from its children (the same boxes a build over the same positions would make).
void IrradianceRecordTree::refit(std::uint32_t self) {
    IrradianceTreeNode& node = nodes_[self];
    if (node.count > 0) {
        bound(node, node.first, node.first + node.count);
        return;
    }
    refit(self + 1);
    refit(node.first);
    const IrradianceTreeNode &left = nodes_[self + 1], &right = nodes_[node.first];
    node.lo = glm::min(left.lo, right.lo);
    node.hi = glm::max(left.hi, right.hi);
    node.sphere_lo = glm::min(left.sphere_lo, right.sphere_lo);
    node.sphere_hi = glm::max(left.sphere_hi, right.sphere_hi);
}

// Median split on the longest axis of the positions; the depth limit keeps the lookup's stack
// bounded (at 60 levels a leaf holds the rest).
void IrradianceRecordTree::build(std::uint32_t begin, std::uint32_t end, int depth) {
    const std::uint32_t self = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    bound(nodes_[self], begin, end);
    glm::vec3 plo(1e30f), phi(-1e30f);
    for (std::uint32_t i = begin; i < end; ++i) {
        plo = glm::min(plo, records_[order_[i]].position);
        phi = glm::max(phi, records_[order_[i]].position);
    }
    if (end - begin <= kLeafRecords || depth >= 60) {
        nodes_[self].first = begin;
        nodes_[self].count = end - begin;
        return;
    }
    const glm::vec3 extent = phi - plo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::uint32_t mid = begin + (end - begin) / 2;
    // Ties broken by index so the tree does not depend on the standard library's partitioning.
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t a, std::uint32_t b) {
                         const float pa = records_[a].position[axis], pb = records_[b].position[axis];
                         return pa < pb || (pa == pb && a < b);
                     });
    build(begin, mid, depth + 1);
    nodes_[self].first = static_cast<std::uint32_t>(nodes_.size());
    nodes_[self].count = 0;
    build(mid, end, depth + 1);
}

IrradianceTreeView IrradianceRecordTree::view() const {
    IrradianceTreeView v;
    v.records = records_.data();
    v.nodes = nodes_.data();
    v.order = order_.data();
    v.node_count = static_cast<std::uint32_t>(nodes_.size());
    v.accuracy = accuracy_;
    return v;
}

}  // namespace kdpm
