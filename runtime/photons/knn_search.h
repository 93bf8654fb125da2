#pragma once
// The k-nearest photon search (k <= kMaxGatherK): a stack-based kd-tree walk that visits the
// near child first, pushes the far child with its squared split-plane distance, and keeps the
// k best photons (KnnBest) whose farthest shrinks the search radius.
//
// Metric: squared distance of an offset (dx, dy, dz) = photon - query; it must be at least the
// Euclidean squared distance (so the split-plane test stays a valid lower bound): Euclidean,
// or DiscMetric, which flattens the search sphere toward a surface against light leaks.
// Accept: photon index -> bool, a filter applied to photons inside the current radius.
#include <cassert>
#include <concepts>
#include <cstdint>

#include <glm/glm.hpp>

#include "formats/host_device.h"
#include "runtime/photons/knn_best.h"
#include "runtime/photons/photon_map_view.h"

#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
#include <xmmintrin.h>
#endif

namespace kdpm {

struct EuclideanMetric {
    KDPM_HD float operator()(float dx, float dy, float dz) const { return dx * dx + dy * dy + dz * dz; }
};

// d^2 + flatten * (d . n)^2: an ellipsoid whose axis along the unit normal n is shorter by
// sqrt(1 + flatten), so photons on nearby parallel surfaces (the other side of a wall) count less.
struct DiscMetric {
    glm::vec3 normal;
    float flatten;
    KDPM_HD float operator()(float dx, float dy, float dz) const {
        float dn = dx * normal.x + dy * normal.y + dz * normal.z;
        return dx * dx + dy * dy + dz * dz + flatten * dn * dn;
    }
};

struct AcceptAll {
    KDPM_HD bool operator()(std::uint32_t) const { return true; }
};

// An Accept that can also decide 16 consecutive photons at once (CPU leaf scans):
// accepted16(base) has bit j set when accept(base + j) holds (asked only where base + 16 <=
// photon_count), used while batched() says so.
template <class Accept>
concept AcceptsSixteen = requires(const Accept& a, std::uint32_t base) {
    { a.batched() } -> std::convertible_to<bool>;
    { a.accepted16(base) } -> std::convertible_to<std::uint32_t>;
};

// An Accept that can rule out every photon below a node at once (rejects_node(node) true only
// when accept would refuse each of them): such subtrees are passed over unvisited.
template <class Accept>
concept RejectsNodes = requires(const Accept& a, std::uint32_t node) {
    { a.rejects_node(node) } -> std::convertible_to<bool>;
};

namespace knn_detail {

// Squared metric distances of m photons (coordinate arrays x, y, z) from q, into out[0..m).
inline constexpr std::uint32_t kLeafChunk = 16;
template <class Metric>
KDPM_HD KDPM_INLINE void leaf_distances(const float* x, const float* y, const float* z, std::uint32_t m, glm::vec3 q,
                                        const Metric& metric, float* out) {
    for (std::uint32_t j = 0; j < m; ++j) out[j] = metric(x[j] - q.x, y[j] - q.y, z[j] - q.z);
}

// Bit j set when d2[j] < max_d2, for the distances of a leaf chunk (AcceptsSixteen's width).
static_assert(kLeafChunk == 16, "accepted16 masks and closer_than masks must cover one chunk");
KDPM_HD KDPM_INLINE std::uint32_t closer_than(const float* d2, float max_d2) {
    std::uint32_t mask = 0;
#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
    const __m128 limit = _mm_set1_ps(max_d2);
    for (std::uint32_t i = 0; i < kLeafChunk; i += 4)
        mask |= static_cast<std::uint32_t>(_mm_movemask_ps(_mm_cmplt_ps(_mm_loadu_ps(d2 + i), limit))) << i;
#else
    for (std::uint32_t i = 0; i < kLeafChunk; ++i) mask |= static_cast<std::uint32_t>(d2[i] < max_d2) << i;
#endif
    return mask;
}

}  // namespace knn_detail

// Finds up to k photons (k clamped to 1..kMaxGatherK) with metric distance^2 < max_radius^2
// (no limit when max_radius <= 0). Returns how many; they are in heap.d2/heap.index[0..count),
// heap.d2[0] the largest, the rest unordered. Writes nothing but heap; no allocation.
//
// A far child is pushed with the squared distance from q to its cell, from the cell's per-axis
// offsets kept incrementally (Arya & Mount: only the split axis changes from the parent's).
// That bound prunes more than the split-plane distance alone.
template <class Metric, class Accept>
KDPM_HD std::uint32_t knn_search(const PhotonMapView& map, glm::vec3 q, std::uint32_t k, float max_radius,
                                 const Metric& metric, const Accept& accept, KnnHeap& heap) {
    if (map.node_count == 0) return 0;
    k = clamp_gather_k(k);
    float max_d2 = max_radius > 0.0f ? max_radius * max_radius : 3.402823466e38f;
    knn_detail::KnnBest best(heap, k);
    // Copies the optimiser may keep in registers: stores into the result could alias the originals.
    const Metric dist = metric;
    const Accept acc = accept;

    struct Entry {
        std::uint32_t node;
        float d2;        // squared distance from q to the cell
        float off[3];    // per-axis offset from q to the cell (0 inside the slab)
    };
    // At most one entry per inner node on the current path: the .kdp validator refuses trees
    // deeper than kMaxPhotonTreeDepth, so the guard below never drops a push for a loaded file;
    // debug builds assert it. One spare entry takes the write of a push that is not kept.
    Entry stack[kMaxPhotonTreeDepth + 2];
    std::uint32_t top = 0;
    std::uint32_t node = 0;
    float off[3] = {0.0f, 0.0f, 0.0f};
    const float qc[3] = {q.x, q.y, q.z};
    for (;;) {
        KdNode n = map.nodes[node];
        while (!n.is_leaf()) {
            const int axis = n.axis();
            const float d = qc[axis] - n.split();
            const std::uint32_t above = n.above_child();
            const std::uint32_t near_child = d < 0.0f ? node + 1 : above;
            const std::uint32_t far_child = d < 0.0f ? above : node + 1;
            // Summed afresh in the photon distance's order (no cancellation), so rounding never
            // makes the bound exceed the distance of a photon in that cell.
            float far_off[3] = {off[0], off[1], off[2]};
            far_off[axis] = d;
            const float far_d2 = far_off[0] * far_off[0] + far_off[1] * far_off[1] + far_off[2] * far_off[2];
            assert(top <= kMaxPhotonTreeDepth && "photon tree deeper than kMaxPhotonTreeDepth");
            // Written always, kept (top advanced) only when the far cell is within the radius:
            // whether it is cannot be predicted well, and a mispredicted branch costs more.
            Entry& e = stack[top];
            e.node = far_child;
            e.d2 = far_d2;
            e.off[0] = far_off[0];
            e.off[1] = far_off[1];
            e.off[2] = far_off[2];
            top += static_cast<std::uint32_t>(far_d2 < max_d2) & static_cast<std::uint32_t>(top <= kMaxPhotonTreeDepth);
            node = near_child;
            n = map.nodes[node];
        }
        const std::uint32_t first = n.first(), end = first + n.count();
        // An accepted photon, kept when (still) closer than the current radius.
        auto keep = [&](std::uint32_t p, float d2) {
            if (d2 < max_d2) {
                if (best.full()) {
                    best.replace_farthest(d2, p);
                    max_d2 = best.farthest();
                } else if (best.append(d2, p)) {
                    max_d2 = best.farthest();
                }
            }
        };
        // Photons in leaf order, each kept when closer than the current radius and accepted.
        auto consider = [&](std::uint32_t p, float d2) {
            if (d2 < max_d2 && acc(p)) keep(p, d2);
        };
#if defined(__CUDA_ARCH__)
        for (std::uint32_t p = first; p < end; ++p)
            consider(p, dist(map.x[p] - q.x, map.y[p] - q.y, map.z[p] - q.z));
#else
        // On the CPU, the distances of a chunk of the leaf first, in a branch-free loop over the
        // coordinate arrays that the compiler vectorises; each is the same float expression as
        // the scalar one, and the photons are then considered in the same order.
        bool batched = false;
        if constexpr (AcceptsSixteen<Accept>) batched = acc.batched();
        for (std::uint32_t base = first; base < end; base += knn_detail::kLeafChunk) {
            const std::uint32_t m = end - base < knn_detail::kLeafChunk ? end - base : knn_detail::kLeafChunk;
            float d2[knn_detail::kLeafChunk];
            // A whole chunk where the arrays go on that far: a fixed trip count, no epilogue
            // branches; the distances past the leaf's end are not looked at.
            const bool whole = base + knn_detail::kLeafChunk <= map.photon_count;
            if (whole)
                knn_detail::leaf_distances(map.x + base, map.y + base, map.z + base, knn_detail::kLeafChunk, q, dist, d2);
            else
                knn_detail::leaf_distances(map.x + base, map.y + base, map.z + base, m, q, dist, d2);
            if constexpr (AcceptsSixteen<Accept>) {
                // Only the photons inside the radius and accepted, found from two bit masks:
                // many of those inside fail a surface filter, and a branch per photon on
                // "inside and accepted" mispredicts often. Still in leaf order.
                if (batched && whole) {
                    std::uint32_t todo = acc.accepted16(base) & knn_detail::closer_than(d2, max_d2) &
                                         (0xffffu >> (knn_detail::kLeafChunk - m));
                    while (todo != 0) {
                        const std::uint32_t j = static_cast<std::uint32_t>(__builtin_ctz(todo));
                        todo &= todo - 1;
                        keep(base + j, d2[j]);
                    }
                    continue;
                }
            }
            for (std::uint32_t j = 0; j < m; ++j) consider(base + j, d2[j]);
        }
#endif
        // Next subtree whose cell is still closer than the current radius and that may hold an
        // accepted photon. Asked of popped subtrees only: on the way down, a test per node or per
        // leaf costs more than it saves.
        for (;;) {
            if (top == 0) return best.finish();
            --top;
            if (stack[top].d2 < max_d2) {
                if constexpr (RejectsNodes<Accept>)
                    if (acc.rejects_node(stack[top].node)) continue;
                break;
            }
        }
        const Entry& e = stack[top];
        node = e.node;
        off[0] = e.off[0];
        off[1] = e.off[1];
        off[2] = e.off[2];
    }
}

KDPM_HD inline std::uint32_t knn_search(const PhotonMapView& map, glm::vec3 q, std::uint32_t k, float max_radius,
                                        KnnHeap& heap) {
    return knn_search(map, q, k, max_radius, EuclideanMetric{}, AcceptAll{}, heap);
}

}  // namespace kdpm
