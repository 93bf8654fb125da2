#pragma once
// The photon gather of the CPU backend: a work item gathers the 64 pixels of an 8x8 tile (64
// consecutive work items of the tiled order) in turn. Each search of a first diffuse vertex
// starts from the radii of the queries just made (RadiusHints) instead of the search limit, and,
// where the photons' vectors are not decoded (memory short), reads back the surface filter's
// decisions for photons its neighbours on the same face have already judged (FilterMemo; with
// decoded vectors the filter judges 16 photons at once instead, and the searches skip subtrees
// whose vector boxes it refuses, PhotonMapView::vector_bounds). The same photons as the
// per-pixel pass (PhotonGatherPass, the GPU's one pixel per thread), found with less work. The
// tiles are fixed, so the image does not depend on the thread count.
#include <cstdint>

#include <glm/vec3.hpp>

#include "runtime/photons/filter_memo.h"
#include "runtime/photons/radiance_estimate.h"
#include "runtime/photons/radius_hints.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/passes/photon_gather_pass.h"
#include "runtime/render/tile_order.h"

namespace kdpm {

struct PhotonTileGatherPass {
    static constexpr std::uint32_t kGroup = kTileSize * kTileSize;
    PhotonGatherPass pass;

    static std::uint64_t work_items(const FrameBuffersView& frame) {
        const std::uint64_t pixels = static_cast<std::uint64_t>(frame.width) * frame.height;
        return (pixels + kGroup - 1) / kGroup;
    }

    void operator()(std::uint64_t item) const {
        const FrameBuffersView& frame = pass.frame;
        const std::uint64_t pixels = static_cast<std::uint64_t>(frame.width) * frame.height;
        const std::uint64_t begin = item * kGroup;
        const std::uint64_t end = begin + kGroup < pixels ? begin + kGroup : pixels;

        KnnHeap heap;
        RadiusHints global_hints, caustic_hints;
        // One per thread (zeroed once), remembering within this tile only: a map freed since
        // could have left its address to another.
        static thread_local FilterMemo global_memo, caustic_memo;
        global_memo.forget();
        caustic_memo.forget();
        auto estimate = [&](const PhotonMapView& map, bool caustic, const DiffuseVertex& v, std::uint32_t index,
                            const RadianceEstimateParams& params, KnnHeap& h) {
            if (index != 0)  // behind a mirror or glass: not among the tile's neighbours
                return estimate_radiance(map, v.position, v.shading_normal, v.albedo, params, h).radiance;
            RadiusHints& hints = caustic ? caustic_hints : global_hints;
            FilterMemo* memo = caustic ? &caustic_memo : &global_memo;
            return estimate_radiance_near(map, v.position, v.shading_normal, v.albedo, params, h, hints, memo).radiance;
        };
        for (std::uint64_t t = begin; t < end; ++t)
            pass.gather_pixel(tiled_pixel(t, frame.width, frame.height), heap, estimate);
    }
};

}  // namespace kdpm
