#include "runtime/render/final_gather/irradiance_cache.h"

#include <algorithm>
#include <vector>

#include <tbb/task_group.h>

#include "runtime/backend/cpu_device.h"
#include "runtime/render/camera.h"
#include "runtime/render/final_gather/cached_gather_pass.h"
#include "runtime/render/final_gather/irradiance_record_pass.h"

namespace kdpm {

void run_cached_gather(CpuDevice& dev, IrradianceCache& cache, const FinalGatherPass& pass,
                       const PinholeCamera& camera) {
    const FrameBuffersView& frame = pass.frame;
    const std::uint32_t w = frame.width, h = frame.height;
    int level = 0;
    for (std::uint32_t stride : {16u, 8u, 4u, 2u, 1u, 1u}) {
        const bool refill = ++level == 6;  // every pixel again, after the finest level's clamps
        std::vector<std::uint64_t> candidates;
        for (std::uint32_t y = 0; y < h; y += stride)
            for (std::uint32_t x = 0; x < w; x += stride) {
                if (!refill && stride < 16 && x % (2 * stride) == 0 && y % (2 * stride) == 0)
                    continue;  // a coarser level's
                const std::uint64_t pixel = static_cast<std::uint64_t>(y) * w + x;
                const std::uint32_t count = frame.vertex_count[pixel];
                for (std::uint32_t i = 0; i < count && i < kMaxDiffuseVertices; ++i)
                    candidates.push_back(frame.vertex_slot(pixel, i));
            }
        std::vector<unsigned char> uncovered(candidates.size());
        const IrradianceTreeView view = cache.tree.view();
        dev.launch(candidates.size(), [&](std::uint64_t c) {
            const DiffuseVertex& v = frame.vertices[candidates[c]];
            glm::vec3 unused;
            uncovered[c] = !view.interpolate(v.position, v.geometric_normal, unused);
        });
        std::vector<std::uint64_t> slots;
        for (std::size_t c = 0; c < candidates.size(); ++c)
            if (uncovered[c]) slots.push_back(candidates[c]);
        if (slots.empty()) continue;
        std::vector<IrradianceRecord> records(slots.size());
        IrradianceRecordPass make{pass, slots.data(), records.data(), cache.min_radius, cache.max_radius};
        make.eye = camera.eye;
        make.pixel_spread = camera.pixel_spread();
        make.min_reach_pixels = std::max(kMinRecordReachPixels, kMinRecordReach * static_cast<float>(camera.height));
        make.accuracy = cache.tree.accuracy();
        dev.launch(slots.size(), make);
        // A cancelled frame (the viewer's stale refinement) stops its loops part-way: records it
        // did not finish must not enter a cache that later frames keep.
        if (tbb::is_current_task_group_canceling()) return;
        cache.tree.add(records);
    }
    dev.launch(static_cast<std::uint64_t>(w) * h, CachedGatherPass{pass, cache.tree.view()});
    for (std::uint64_t p = 0; p < static_cast<std::uint64_t>(w) * h; ++p)
        cache.points += frame.vertex_count[p] < kMaxDiffuseVertices ? frame.vertex_count[p] : kMaxDiffuseVertices;
}

}  // namespace kdpm
