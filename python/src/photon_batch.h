#pragma once
// Batches of k-nearest searches and radiance estimates over a photon map on every CPU thread:
// one knn_search / estimate_radiance per query, as the renderer's gather runs them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include <glm/vec3.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/photons/knn_search.h"
#include "runtime/photons/radiance_estimate.h"
#include "runtime/photons/radius_hints.h"

namespace kdpm::python {

struct KnnQueries {
    const float* points;   // 3 per query
    const float* normals;  // 3 per query (unit), or null: every photon counts
    std::uint64_t count;
    std::uint32_t k;
    float max_radius;      // <= 0: unlimited
    float min_normal_cos;  // with normals: the photon's stored normal . normal must reach it
};

// dist/index: k per query, nearest first (ties by index); past the photons found, +inf and
// map.photon_count, as SciPy's cKDTree.query fills them. Each run of consecutive queries starts
// its searches from the radii of the ones before (RadiusHints): the same k nearest, found sooner
// when neighbouring queries are near each other, as a frame's pixels are.
inline void knn_batch(const PhotonMapView& map, const KnnQueries& q, float* dist, std::int64_t* index) {
    tbb::parallel_for(tbb::blocked_range<std::uint64_t>(0, q.count, 64), [&](const tbb::blocked_range<std::uint64_t>& r) {
        RadiusHints hints;
        KnnHeap heap;
        for (std::uint64_t i = r.begin(); i != r.end(); ++i) {
            const float* p = q.points + 3 * i;
            const glm::vec3 point(p[0], p[1], p[2]);
            std::uint32_t found = 0;
            if (q.normals) {
                const float* n = q.normals + 3 * i;
                const glm::vec3 normal(n[0], n[1], n[2]);
                const SurfacePhotonFilter filter(map, normal, q.min_normal_cos, 0, 0);
                found = search_from_hint(
                    [&](float limit) { return knn_search(map, point, q.k, limit, EuclideanMetric{}, filter, heap); },
                    q.k, hints.hint(point, normal), q.max_radius);
                if (found == q.k) hints.remember(point, normal, std::sqrt(heap.d2[0]));
            } else {
                found = search_from_hint([&](float limit) { return knn_search(map, point, q.k, limit, heap); }, q.k,
                                         hints.hint(point), q.max_radius);
                if (found == q.k) hints.remember(point, std::sqrt(heap.d2[0]));
            }
            std::pair<float, std::uint32_t> order[kMaxGatherK];
            for (std::uint32_t j = 0; j < found; ++j) order[j] = {heap.d2[j], heap.index[j]};
            std::sort(order, order + found);
            float* d = dist + q.k * i;
            std::int64_t* x = index + q.k * i;
            for (std::uint32_t j = 0; j < q.k; ++j) {
                d[j] = j < found ? std::sqrt(order[j].first) : __builtin_inff();
                x[j] = j < found ? order[j].second : map.photon_count;
            }
        }
    });
}

// Outgoing radiance (3 per query) of a diffuse surface of `albedo` at each point: Jensen's
// estimate over the k nearest photons that may light it (estimate_radiance).
inline void radiance_batch(const PhotonMapView& map, const float* points, const float* normals, std::uint64_t count,
                           glm::vec3 albedo, const RadianceEstimateParams& params, float* radiance) {
    cpu_parallel_for(count, [&](std::uint64_t i) {
        KnnHeap heap;
        const float* p = points + 3 * i;
        const float* n = normals + 3 * i;
        const RadianceEstimate e = estimate_radiance(map, glm::vec3(p[0], p[1], p[2]), glm::vec3(n[0], n[1], n[2]),
                                                     albedo, params, heap);
        radiance[3 * i] = e.radiance.x;
        radiance[3 * i + 1] = e.radiance.y;
        radiance[3 * i + 2] = e.radiance.z;
    }, 64);
}

}  // namespace kdpm::python
