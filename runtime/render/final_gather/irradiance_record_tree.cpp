#include "runtime/render/final_gather/irradiance_record_tree.h"

#include <algorithm>

namespace kdpm {

namespace {
constexpr std::uint32_t kLeafRecords = 4;
}

void IrradianceRecordTree::add(const std::vector<IrradianceRecord>& records) {
    records_.insert(records_.end(), records.begin(), records.end());
    order_.resize(records_.size());
    for (std::uint32_t i = 0; i < order_.size(); ++i) order_[i] = i;
    nodes_.clear();
    if (!records_.empty()) build(0, static_cast<std::uint32_t>(order_.size()), 0);
}

// Median split on the longest axis of the positions; the depth limit keeps the lookup's stack
// bounded (at 60 levels a leaf holds the rest).
void IrradianceRecordTree::build(std::uint32_t begin, std::uint32_t end, int depth) {
    const std::uint32_t self = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    glm::vec3 lo(1e30f), hi(-1e30f), plo(1e30f), phi(-1e30f);
    for (std::uint32_t i = begin; i < end; ++i) {
        const IrradianceRecord& r = records_[order_[i]];
        const glm::vec3 reach(accuracy_ * r.radius);
        lo = glm::min(lo, r.position - reach);
        hi = glm::max(hi, r.position + reach);
        plo = glm::min(plo, r.position);
        phi = glm::max(phi, r.position);
    }
    nodes_[self].lo = lo;
    nodes_[self].hi = hi;
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
