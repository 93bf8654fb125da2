#include "runtime/render/final_gather/irradiance_record_tree.h"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

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
    rebuild();  // the valid spheres have shrunk
}

void IrradianceRecordTree::rebuild() {
    order_.resize(records_.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    nodes_.clear();
    if (!records_.empty()) build(0, static_cast<std::uint32_t>(order_.size()), 0);
}

// Every record i with |p_i - p_j| < max(R_i, R_j): the nodes whose R-spheres meet the ball of
// radius R_j around p_j hold them all (p_j lies in the R-sphere of the first kind).
void IrradianceRecordTree::clamp_by_neighbours(std::uint32_t j) {
    std::vector<std::uint32_t> stack{0};
    while (!stack.empty()) {
        const IrradianceTreeNode& node = nodes_[stack.back()];
        const auto self = stack.back();
        stack.pop_back();
        IrradianceRecord& rj = records_[j];
        const glm::vec3 nearest = glm::clamp(rj.position, node.sphere_lo, node.sphere_hi);
        const glm::vec3 gap = nearest - rj.position;
        if (glm::dot(gap, gap) > rj.radius * rj.radius) continue;
        if (node.count == 0) {
            stack.push_back(node.first);
            stack.push_back(self + 1);
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

// Median split on the longest axis of the positions; the depth limit keeps the lookup's stack
// bounded (at 60 levels a leaf holds the rest).
void IrradianceRecordTree::build(std::uint32_t begin, std::uint32_t end, int depth) {
    const std::uint32_t self = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    glm::vec3 lo(1e30f), hi(-1e30f), plo(1e30f), phi(-1e30f), slo(1e30f), shi(-1e30f);
    for (std::uint32_t i = begin; i < end; ++i) {
        const IrradianceRecord& r = records_[order_[i]];
        const glm::vec3 reach(accuracy_ * r.radius);
        lo = glm::min(lo, r.position - reach);
        hi = glm::max(hi, r.position + reach);
        slo = glm::min(slo, r.position - glm::vec3(r.radius));
        shi = glm::max(shi, r.position + glm::vec3(r.radius));
        plo = glm::min(plo, r.position);
        phi = glm::max(phi, r.position);
    }
    nodes_[self].lo = lo;
    nodes_[self].hi = hi;
    nodes_[self].sphere_lo = slo;
    nodes_[self].sphere_hi = shi;
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
