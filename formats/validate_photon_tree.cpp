#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "formats/photon_layout.h"
#include "formats/scene_limits.h"
#include "formats/section_ids.h"
#include "formats/validate_kinds.h"

namespace kdpm {
namespace {

// One photon map of a .kdp: sections present with matching counts, nodes forming one tree in
// depth-first order no deeper than kMaxPhotonTreeDepth, leaves covering the photons exactly
// once in order, every photon inside its leaf's cell, finite positions, known flags.
void validate_map(const ContainerReader& file, PhotonMapKind map) {
    const std::string label = map == PhotonMapKind::global    ? "photon tree"
                              : map == PhotonMapKind::caustic ? "caustic tree"
                                                              : "irradiance tree";
    auto fail = [&](const std::string& why) { throw FormatError(file.name() + ": " + label + ": " + why); };
    auto id = [&](PhotonTreeField f) { return photon_tree_section(map, f); };

    const auto& info = file.record<PhotonTreeInfo>(id(ptree_field_info));
    auto nodes = file.section<KdNode>(id(ptree_field_nodes));
    auto x = file.section<float>(id(ptree_field_x));
    auto y = file.section<float>(id(ptree_field_y));
    auto z = file.section<float>(id(ptree_field_z));
    auto power = file.section<std::uint32_t>(id(ptree_field_power));
    auto dirs = file.section<PackedPhotonDirections>(id(ptree_field_directions));
    auto flags = file.section<std::uint32_t>(id(ptree_field_flags));

    const std::uint64_t n = info.photon_count;
    if (x.size() != n || y.size() != n || z.size() != n || power.size() != n || dirs.size() != n || flags.size() != n)
        fail("photon arrays do not all hold photon_count = " + std::to_string(n) + " entries");
    if (nodes.empty()) fail("no nodes");
    if (nodes.size() != info.node_count) fail("node_count does not match the nodes section");
    if (info.builder > 1) fail("unknown builder " + std::to_string(info.builder));
    for (int a = 0; a < 3; ++a)
        if (!std::isfinite(info.bounds_min[a]) || !std::isfinite(info.bounds_max[a]) ||
            info.bounds_min[a] > info.bounds_max[a])
            fail("bounds are not finite and ordered");
    if (info.max_depth > kMaxPhotonTreeDepth) fail("max_depth exceeds " + std::to_string(kMaxPhotonTreeDepth));
    // The renderer derives its search radius from query_radius.
    if (!(info.query_radius >= 0.0f) || !std::isfinite(info.query_radius) ||
        radius_too_small(info.query_radius, info.bounds_min, info.bounds_max))
        fail("query_radius " + radius_limit_text(info.query_radius, info.bounds_min, info.bounds_max) +
             " (or negative, or not finite)");

    const float* coord[3] = {x.data(), y.data(), z.data()};
    // A load checks every photon: first in one branch-free sweep (vectorised), and only a file
    // that fails it photon by photon, to name the first bad one.
    std::uint32_t bad = 0;  // nonzero once a photon fails (bits of flags or 1)
    const float big = std::numeric_limits<float>::max();
    auto not_finite = [big](float c) { return static_cast<std::uint32_t>(!(std::fabs(c) <= big)); };
    for (std::uint64_t i = 0; i < n; ++i)
        bad |= not_finite(x[i]) | not_finite(y[i]) | not_finite(z[i]) | (flags[i] & ~kPhotonKnownFlags) |
               static_cast<std::uint32_t>(photon_bounce(flags[i]) > info.max_bounces);
    for (std::uint64_t i = 0; i < n && bad != 0; ++i) {
        if (!std::isfinite(x[i]) || !std::isfinite(y[i]) || !std::isfinite(z[i]))
            fail("photon " + std::to_string(i) + " has a non-finite position");
        if (flags[i] & ~kPhotonKnownFlags) fail("photon " + std::to_string(i) + " has unknown flag bits");
        if (photon_bounce(flags[i]) > info.max_bounces) fail("photon " + std::to_string(i) + " has a bounce beyond max_bounces");
    }

    // Pre-order walk: the k-th visited node must be node k, so the nodes are exactly one tree.
    // A cell holds lo <= c < hi on each axis. The root's bounds are closed (c <= bounds_max):
    // with finite coordinates that is c < the next float up, so every axis takes one test.
    struct Item {
        std::uint32_t node, depth;
        float lo[3], hi[3];
    };
    std::vector<Item> stack;
    stack.reserve(2 * kMaxPhotonTreeDepth + 2);
    Item root{0, 0, {}, {}};
    for (int a = 0; a < 3; ++a) {
        root.lo[a] = info.bounds_min[a];
        root.hi[a] = std::nextafter(info.bounds_max[a], std::numeric_limits<float>::infinity());
    }
    std::uint64_t visited = 0, next_photon = 0, leaves = 0;
    std::uint32_t depth_seen = 0, largest_leaf = 0;
    // The "below" child is walked next in place; only the "above" child goes on the stack.
    Item it = root;
    for (bool more = true; more;) {
        if (it.node != visited) fail("nodes are not one tree in depth-first order (node " + std::to_string(it.node) + ")");
        ++visited;
        if (it.depth > kMaxPhotonTreeDepth) fail("deeper than " + std::to_string(kMaxPhotonTreeDepth));
        depth_seen = std::max(depth_seen, it.depth);
        const KdNode& node = nodes[it.node];
        if (node.is_leaf()) {
            ++leaves;
            largest_leaf = std::max(largest_leaf, node.count());
            if (node.first() != next_photon)
                fail("leaf " + std::to_string(it.node) + " starts at photon " + std::to_string(node.first()) +
                     ", expected " + std::to_string(next_photon));
            if (node.count() > n - next_photon) fail("leaf " + std::to_string(it.node) + " runs past the photons");
            const std::uint64_t begin = node.first(), end = begin + std::uint64_t{node.count()};
            // All three axes in one branch-free loop (three loops, one per axis, spent more on
            // their set-up than on a leaf's few photons); the sweep above has refused non-finite
            // coordinates, so the comparisons are exact.
            std::uint32_t inside = 1;
            {
                const float lx = it.lo[0], ly = it.lo[1], lz = it.lo[2], hx = it.hi[0], hy = it.hi[1], hz = it.hi[2];
                for (std::uint64_t p = begin; p < end; ++p)
                    inside &= static_cast<std::uint32_t>(x[p] >= lx) & static_cast<std::uint32_t>(x[p] < hx) &
                              static_cast<std::uint32_t>(y[p] >= ly) & static_cast<std::uint32_t>(y[p] < hy) &
                              static_cast<std::uint32_t>(z[p] >= lz) & static_cast<std::uint32_t>(z[p] < hz);
            }
            for (std::uint64_t p = begin; p < end && !inside; ++p)
                for (int a = 0; a < 3; ++a)
                    if (!(coord[a][p] >= it.lo[a] && coord[a][p] < it.hi[a]))
                        fail("photon " + std::to_string(p) + " lies outside the cell of leaf " + std::to_string(it.node));
            next_photon += node.count();
            more = !stack.empty();
            if (more) {
                it = stack.back();
                stack.pop_back();
            }
            continue;
        }
        const int axis = node.axis();
        const float s = node.split();
        const std::uint32_t above = node.above_child();
        if (!std::isfinite(s)) fail("node " + std::to_string(it.node) + " has a non-finite split");
        if (above <= it.node + 1 || above >= nodes.size() || it.node + 1 >= nodes.size())
            fail("node " + std::to_string(it.node) + " has a child index out of range");
        Item& hi = stack.emplace_back(it);
        hi.node = above;
        hi.depth = it.depth + 1;
        hi.lo[axis] = s;
        it.node = it.node + 1;
        it.depth = hi.depth;
        it.hi[axis] = s;
    }
    if (visited != nodes.size()) fail("unreachable nodes");
    if (next_photon != n) fail("leaves cover " + std::to_string(next_photon) + " of " + std::to_string(n) + " photons");
    if (leaves != info.leaf_count || depth_seen != info.max_depth || largest_leaf != info.max_leaf_size)
        fail("info statistics (leaves, depth, largest leaf) do not match the nodes");
}

// The irradiance map's own sections (its tree is checked by validate_map): one irradiance and
// one source index per photon, irradiance finite and >= 0, each source a distinct photon of the
// global map at the same position.
void validate_irradiance(const ContainerReader& file) {
    auto fail = [&](const std::string& why) { throw FormatError(file.name() + ": irradiance tree: " + why); };
    auto id = [](PhotonMapKind map, PhotonTreeField f) { return photon_tree_section(map, f); };
    const auto& info = file.record<PhotonTreeInfo>(id(PhotonMapKind::irradiance, ptree_field_info));
    const auto& global = file.record<PhotonTreeInfo>(id(PhotonMapKind::global, ptree_field_info));
    auto irradiance = file.section<PrecomputedIrradiance>(id(PhotonMapKind::irradiance, ptree_field_irradiance));
    auto source = file.section<std::uint32_t>(id(PhotonMapKind::irradiance, ptree_field_source));
    const std::uint64_t n = info.photon_count;
    if (irradiance.size() != n || source.size() != n)
        fail("irradiance and source do not both hold photon_count = " + std::to_string(n) + " entries");
    if (n > global.photon_count) fail("more photons than the global map");
    auto x = file.section<float>(id(PhotonMapKind::irradiance, ptree_field_x));
    auto y = file.section<float>(id(PhotonMapKind::irradiance, ptree_field_y));
    auto z = file.section<float>(id(PhotonMapKind::irradiance, ptree_field_z));
    auto gx = file.section<float>(id(PhotonMapKind::global, ptree_field_x));
    auto gy = file.section<float>(id(PhotonMapKind::global, ptree_field_y));
    auto gz = file.section<float>(id(PhotonMapKind::global, ptree_field_z));
    // The global map's own pass checks these sizes too, but may not have run yet.
    if (x.size() != n || y.size() != n || z.size() != n || gx.size() != global.photon_count ||
        gy.size() != global.photon_count || gz.size() != global.photon_count)
        fail("photon positions do not match the photon counts");
    std::vector<bool> used(global.photon_count, false);
    for (std::uint64_t i = 0; i < n; ++i) {
        // Spelled only for a message: building it for every photon would slow a load noticeably.
        auto which = [i] { return "photon " + std::to_string(i); };
        for (float c : irradiance[i].rgb)
            if (!std::isfinite(c) || c < 0.0f) fail(which() + " has a non-finite or negative irradiance");
        const std::uint32_t s = source[i];
        if (s >= global.photon_count)
            fail(which() + " names global photon " + std::to_string(s) + " of " + std::to_string(global.photon_count));
        if (used[s]) fail(which() + " names global photon " + std::to_string(s) + " a second time");
        used[s] = true;
        if (x[i] != gx[s] || y[i] != gy[s] || z[i] != gz[s])
            fail(which() + " is not at the position of global photon " + std::to_string(s));
    }
}

}  // namespace

std::vector<std::function<void()>> photon_tree_passes(const ContainerReader& file, const ValidationOptions&) {
    std::vector<std::function<void()>> passes;
    passes.push_back([&file] { validate_map(file, PhotonMapKind::global); });
    if (file.find(photon_tree_section(PhotonMapKind::caustic, ptree_field_info)))
        passes.push_back([&file] { validate_map(file, PhotonMapKind::caustic); });
    if (file.find(photon_tree_section(PhotonMapKind::irradiance, ptree_field_info))) {
        passes.push_back([&file] { validate_map(file, PhotonMapKind::irradiance); });
        passes.push_back([&file] { validate_irradiance(file); });
    }
    return passes;
}

}  // namespace kdpm
