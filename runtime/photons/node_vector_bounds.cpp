#include "runtime/photons/node_vector_bounds.h"

#include <cmath>
#include <limits>

#include "formats/photon_layout.h"
#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/photons/unpacked_directions.h"

namespace kdpm {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

void set_empty(float* box) {
    for (std::uint32_t c = 0; c < kVectorBoundFloats; ++c) box[c] = 0.0f;
    for (std::uint32_t a = 0; a < 3; ++a) {
        box[a] = box[8 + a] = kInf;
        box[4 + a] = box[12 + a] = -kInf;
    }
    box[kMaxBounceAt] = -1.0f;
    box[kCommonFlagsAt] = static_cast<float>(kPhotonKnownFlags);
}

// The flag summary widened by a photon's flags f, or by a child's summary.
void widen_flags(float* box, float max_bounce, std::uint32_t common) {
    box[kMaxBounceAt] = max_bounce > box[kMaxBounceAt] ? max_bounce : box[kMaxBounceAt];
    box[kCommonFlagsAt] = static_cast<float>(static_cast<std::uint32_t>(box[kCommonFlagsAt]) & common);
}

// Widens lo/hi (at box[lo_at], box[lo_at + 4]) by v; a NaN component makes them unbounded.
void widen(float* box, std::uint32_t lo_at, const float v[3]) {
    for (std::uint32_t a = 0; a < 3; ++a) {
        float& lo = box[lo_at + a];
        float& hi = box[lo_at + 4 + a];
        if (v[a] != v[a]) {
            lo = -kInf;
            hi = kInf;
            continue;
        }
        lo = v[a] < lo ? v[a] : lo;
        hi = v[a] > hi ? v[a] : hi;
    }
}

void widen_by_box(float* box, const float* child) {
    widen_flags(box, child[kMaxBounceAt], static_cast<std::uint32_t>(child[kCommonFlagsAt]));
    for (std::uint32_t c : {0u, 8u})
        for (std::uint32_t a = 0; a < 3; ++a) {
            box[c + a] = child[c + a] < box[c + a] ? child[c + a] : box[c + a];
            box[c + 4 + a] = child[c + 4 + a] > box[c + 4 + a] ? child[c + 4 + a] : box[c + 4 + a];
        }
}

}  // namespace

std::vector<float> bound_node_vectors(const PhotonMapView& map) {
    const std::uint64_t nodes = map.node_count, n = map.photon_count;
    std::vector<float> out(nodes * kVectorBoundFloats);
    if (nodes == 0) return out;
    // Leaves from their photons (in parallel), then inner nodes from their children: a child's
    // index is always above its parent's, so one pass from the last node up sees children first.
    cpu_parallel_for(nodes, [&](std::uint64_t i) {
        float* box = out.data() + i * kVectorBoundFloats;
        set_empty(box);
        const KdNode node = map.nodes[i];
        if (!node.is_leaf()) return;
        const std::uint64_t end = std::uint64_t{node.first()} + node.count();
        for (std::uint64_t p = node.first(); p < end; ++p) {
            const float d[3] = {map.unpacked[p], map.unpacked[n + p], map.unpacked[2 * n + p]};
            const float s[3] = {map.unpacked[3 * n + p], map.unpacked[4 * n + p], map.unpacked[5 * n + p]};
            widen(box, 0, d);
            widen(box, 8, s);
            const std::uint32_t f = map.flags[p];
            widen_flags(box, static_cast<float>(photon_bounce(f)), f & kPhotonKnownFlags);
        }
    }, 1024);
    for (std::uint64_t i = nodes; i-- > 0;) {
        const KdNode node = map.nodes[i];
        if (node.is_leaf()) continue;
        float* box = out.data() + i * kVectorBoundFloats;
        const std::uint64_t above = node.above_child();
        if (i + 1 >= nodes || above <= i || above >= nodes) {  // not a tree a validated file holds
            const float unbounded[3] = {NAN, NAN, NAN};
            widen(box, 0, unbounded);
            widen(box, 8, unbounded);
            widen_flags(box, 255.0f, 0u);
            continue;
        }
        widen_by_box(box, box + kVectorBoundFloats);  // below child: the next node
        widen_by_box(box, out.data() + above * kVectorBoundFloats);
    }
    return out;
}

SearchVectors attach_search_vectors(PhotonMapView& map) {
    SearchVectors kept;
    kept.vectors = unpack_directions(map);
    if (kept.vectors.empty()) return kept;
    map.unpacked = kept.vectors.data();
    kept.bounds = bound_node_vectors(map);
    map.vector_bounds = kept.bounds.data();
    return kept;  // moved: the arrays, and so the view's pointers into them, stay where they are
}

}  // namespace kdpm
