#pragma once
// Batches of single queries as work items, run by both backends' Device: the closest hit of
// each ray, and the k nearest photons of each point. The kernels are the runtime's own
// (closest_hit, knn_search); only the batching is the tests'.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/geometry/ray.h"
#include "runtime/photons/knn_search.h"
#include "runtime/photons/photon_map_view.h"

namespace kdpm::test {

struct ClosestHitsPass {
    GeometryView geometry;
    const Ray* rays = nullptr;
    Hit* hits = nullptr;
    KDPM_HD void operator()(std::uint64_t i) const { hits[i] = closest_hit(geometry, rays[i]); }
};

// found[i], then the heap of query i (k entries: d2 and photon index, heap order).
struct KnnPass {
    PhotonMapView map;
    const glm::vec3* points = nullptr;
    std::uint32_t k = 1;
    std::uint32_t* found = nullptr;
    float* d2 = nullptr;
    std::uint32_t* index = nullptr;
    KDPM_HD void operator()(std::uint64_t i) const {
        KnnHeap heap;
        const std::uint32_t n = knn_search(map, points[i], k, 0.0f, heap);
        found[i] = n;
        for (std::uint32_t j = 0; j < k; ++j) {
            d2[i * k + j] = j < n ? heap.d2[j] : -1.0f;
            index[i * k + j] = j < n ? heap.index[j] : 0xffffffffu;
        }
    }
};

struct KnnResults {
    std::vector<std::uint32_t> found;
    std::vector<float> d2;
    std::vector<std::uint32_t> index;
};

// `geometry` / `map` hold arrays where `dev` runs.
template <class Device>
std::vector<Hit> run_closest_hits(Device& dev, const GeometryView& geometry, const std::vector<Ray>& rays) {
    dev.begin();
    auto device_rays = dev.from_host(rays);
    auto hits = dev.template scratch<Hit>(rays.size());
    dev.launch(rays.size(), ClosestHitsPass{geometry, device_rays.data(), hits.data()});
    std::vector<Hit> out;
    dev.to_host(hits, out);
    return out;
}

template <class Device>
KnnResults run_knn(Device& dev, const PhotonMapView& map, const std::vector<glm::vec3>& points, std::uint32_t k) {
    dev.begin();
    auto device_points = dev.from_host(points);
    auto found = dev.template scratch<std::uint32_t>(points.size());
    auto d2 = dev.template scratch<float>(points.size() * k);
    auto index = dev.template scratch<std::uint32_t>(points.size() * k);
    dev.launch(points.size(), KnnPass{map, device_points.data(), k, found.data(), d2.data(), index.data()});
    KnnResults out;
    dev.to_host(found, out.found);
    dev.to_host(d2, out.d2);
    dev.to_host(index, out.index);
    return out;
}

}  // namespace kdpm::test
