#pragma once
// Photon shooting written once for both backends: batches of paths, the photons of each batch
// appended to the shot in path order. A batch's paths are traced depth first, one work item per
// path (ShootPathsPass, the kernel), each into its own fixed max_bounces + 1 slots that the host
// then compacts; or on the CPU in sorted waves (shoot_waves.h), which gives the same hits faster
// and places each photon straight where it belongs. The hits are
// therefore the same whatever the thread count, the order or the backend runs the paths -- up to
// floating point: see photon_shooter.h for where the CUDA build can differ.
// `Device` is CpuDevice or CudaDevice (scratch<T>(n), launch(n, pass), to_host, begin).
#include <algorithm>
#include <cstdint>
#include <functional>
#include <vector>

#include "formats/host_device.h"
#include "formats/photon_layout.h"
#include "runtime/backend/items_on_host.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/photons/append_path_hits.h"
#include "runtime/photons/photon_path.h"
#include "runtime/photons/shoot_waves.h"
#include "runtime/shading/area_light.h"

namespace kdpm {

// How a batch's paths are traced: each path to its end before the next (GPUs, and peers whose
// intersector prefers it), or all of them a ray at a time in sorted waves (host-memory devices
// only; elsewhere depth first).
enum class PathOrder : std::uint8_t { depth_first, sorted_waves };

// One work item per path of the batch starting at path `first`.
template <class ClosestHit = KdTreeClosestHit>
struct ShootPathsPass {
    GeometryView geometry;
    LightSelection lights;
    ShootSettings settings;
    std::uint64_t first = 0;
    PhotonHit* slots = nullptr;  // (max_bounces + 1) per path of the batch
    PhotonPathResult* results = nullptr;
    ClosestHit intersect{};

    KDPM_HD void operator()(std::uint64_t i) const {
        const std::uint64_t per_path = static_cast<std::uint64_t>(settings.max_bounces) + 1;
        results[i] = trace_photon_path(geometry, lights, settings, first + i, slots + i * per_path, intersect);
    }
};

// Paths per batch: `preferred` (enough to fill the backend), fewer when their slots would take
// more than `max_bytes` (many bounces), at least 1024. The batch size does not change the hits.
inline std::uint64_t shoot_batch_size(std::uint32_t max_bounces, std::uint64_t preferred, std::uint64_t max_bytes) {
    const std::uint64_t per_path = (static_cast<std::uint64_t>(max_bounces) + 1) * sizeof(PhotonHit);
    return std::max<std::uint64_t>(1024, std::min(preferred, max_bytes / per_path));
}

// Paths first_path .. end_path - 1 (a shard, or all). geometry and lights hold arrays where `dev`
// runs. Appends the stored hits to `hits` in path order and returns the rays traced. `intersect`:
// see trace_photon_path.
template <class Device, class ClosestHit = KdTreeClosestHit>
std::uint64_t shoot_paths(Device& dev, const GeometryView& geometry, const LightSelection& lights,
                          const ShootSettings& settings, std::uint64_t first_path, std::uint64_t end_path,
                          std::uint64_t batch, std::vector<PhotonHit>& hits,
                          const std::function<void(double)>& progress, const ClosestHit& intersect = ClosestHit{},
                          PathOrder order = PathOrder::depth_first) {
    const std::uint64_t per_path = static_cast<std::uint64_t>(settings.max_bounces) + 1;
    std::uint64_t rays = 0;
    std::vector<PhotonHit> batch_hits;
    std::vector<PhotonPathResult> batch_results;
    const std::size_t start_size = hits.size();
    for (std::uint64_t first = first_path; first < end_path; first += batch) {
        const std::uint64_t n = std::min(batch, end_path - first);
        const std::uint64_t done = first + n - first_path;  // paths once this batch is traced
        // Room for this batch's photons and, at the rate stored so far, for the batches to come (at
        // least a quarter more than now), so that the hits are not copied again at every doubling.
        // The estimate has 1/32 to spare, more than batches' rates differ, because a last batch
        // that overruns it copies all the hits once more.
        const auto reserve = [&](std::uint64_t batch_stored) {
            const std::uint64_t needed = hits.size() + batch_stored;
            if (hits.capacity() >= needed) return;
            const double rate =
                static_cast<double>(needed - start_size) / static_cast<double>(done) * (1.0 + 1.0 / 32);
            const auto expected =
                start_size + static_cast<std::uint64_t>(rate * static_cast<double>(end_path - first_path));
            hits.reserve(std::max({needed, expected, hits.capacity() + hits.capacity() / 4}));
        };
        dev.begin();
        // Every path writes its result.
        auto results = dev.template scratch<PhotonPathResult>(n);
        const PhotonPathResult* result_items = nullptr;
        if constexpr (arrays_on_host_v<Device>) {
            if (order == PathOrder::sorted_waves && n <= shoot_waves_detail::kWaveMaxBatch &&
                settings.max_bounces <= shoot_waves_detail::kWaveMaxBounces) {
                shoot_batch_in_waves(dev, geometry, lights, settings, first, n, results.data(), hits, reserve,
                                     intersect);
                result_items = results.data();
            }
        }
        if (result_items == nullptr) {
            // Slots past a path's `stored` are never read.
            auto slots = dev.template scratch<PhotonHit>(n * per_path);
            dev.launch(n, ShootPathsPass<ClosestHit>{geometry, lights, settings, first, slots.data(), results.data(),
                                                     intersect});
            const PhotonHit* slot_items = items_on_host(dev, slots, batch_hits);
            result_items = items_on_host(dev, results, batch_results);
            std::uint64_t batch_stored = 0;
            for (std::uint64_t i = 0; i < n; ++i) batch_stored += result_items[i].stored;
            reserve(batch_stored);
            append_path_hits(slot_items, per_path, result_items, n, batch_stored, hits);
        }
        for (std::uint64_t i = 0; i < n; ++i) rays += result_items[i].rays;
        if (progress) progress(static_cast<double>(done) / static_cast<double>(end_path - first_path));
    }
    return rays;
}

}  // namespace kdpm
