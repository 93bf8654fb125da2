#pragma once
// The irradiance cache's lookup structure: a kd-tree over the records' positions whose nodes
// bound the records' valid spheres (radius accuracy * R_i), so a lookup descends only into
// nodes whose bounds hold the query point. Built on the host; the view is plain data.
//
// Records added are clamped by their neighbours first (Krivanek et al. 2006): R_i <= R_j +
// |p_i - p_j| for every pair, so a record made out in the open shrinks once one beside an
// object says geometry is near, and no record reaches far past a smaller one.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/render/final_gather/irradiance_record.h"

namespace kdpm {

struct IrradianceTreeNode {
    glm::vec3 lo, hi;              // bounds of the valid spheres below
    glm::vec3 sphere_lo, sphere_hi;  // bounds of the spheres of radius R_i below (neighbour clamping)
    std::uint32_t first = 0;       // leaf: first index into order; inner: the right child
    std::uint32_t count = 0;       // leaf: records (> 0); inner: 0, the left child follows
};

struct IrradianceTreeView {
    const IrradianceRecord* records = nullptr;
    const IrradianceTreeNode* nodes = nullptr;
    const std::uint32_t* order = nullptr;  // record indices, grouped by leaf
    std::uint32_t node_count = 0;
    float accuracy = 0.2f;

    // Calls visit(index, error) for every record with error < accuracy at (p, n).
    template <class Visit>
    KDPM_HD void for_each_valid(const glm::vec3& p, const glm::vec3& n, Visit&& visit) const {
        if (node_count == 0) return;
        std::uint32_t stack[64];
        std::uint32_t top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const IrradianceTreeNode& node = nodes[stack[--top]];
            if (p.x < node.lo.x || p.y < node.lo.y || p.z < node.lo.z || p.x > node.hi.x || p.y > node.hi.y ||
                p.z > node.hi.z)
                continue;
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    const float e = record_error(records[order[i]], p, n);
                    if (e >= 0.0f && e < accuracy) visit(order[i], e);
                }
                continue;
            }
            const std::uint32_t self = static_cast<std::uint32_t>(&node - nodes);
            if (top + 2 <= 64) {
                stack[top++] = node.first;
                stack[top++] = self + 1;
            }
        }
    }

    // Ward's interpolation: the records' extrapolated irradiance weighted by 1 / e_i. False when
    // no record is valid at (p, n).
    KDPM_HD bool interpolate(const glm::vec3& p, const glm::vec3& n, glm::vec3& irradiance) const {
        glm::vec3 sum(0.0f);
        float weights = 0.0f;
        for_each_valid(p, n, [&](std::uint32_t i, float e) {
            const float w = 1.0f / (e > 1e-6f ? e : 1e-6f);
            sum += w * extrapolated_irradiance(records[i], p, n);
            weights += w;
        });
        if (!(weights > 0.0f)) return false;
        irradiance = sum / weights;
        return true;
    }
};

// The records and their tree, rebuilt on the host as records are added.
class IrradianceRecordTree {
public:
    explicit IrradianceRecordTree(float accuracy) : accuracy_(accuracy) {}
    // Appends records (in the given order), clamps the radii of the new records and of their
    // neighbours, and rebuilds the tree over all of them.
    void add(const std::vector<IrradianceRecord>& records);
    const std::vector<IrradianceRecord>& records() const { return records_; }
    IrradianceTreeView view() const;
    float accuracy() const { return accuracy_; }

private:
    void build(std::uint32_t begin, std::uint32_t end, int depth);
    void rebuild();
    void clamp_by_neighbours(std::uint32_t j);
    void bound(IrradianceTreeNode& node, std::uint32_t begin, std::uint32_t end) const;
    void refit(std::uint32_t node);

    float accuracy_;
    std::vector<IrradianceRecord> records_;
    std::vector<IrradianceTreeNode> nodes_;
    std::vector<std::uint32_t> order_;
    std::vector<std::uint32_t> stack_;  // clamp_by_neighbours' scratch
};

}  // namespace kdpm
