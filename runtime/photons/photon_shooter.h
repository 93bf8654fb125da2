#pragma once
// The CPU driver of the shooting kernel: runs trace_photon_path for every path in batches on
// oneTBB (each path writes only its own max_bounces + 1 slots), then compacts the slots in path
// order, so the hits are identical whatever the thread count.
#include <cstdint>
#include <functional>
#include <vector>

#include "formats/photon_layout.h"
#include "runtime/geometry/geometry_view.h"

namespace kdpm {

struct ShootOptions {
    std::uint64_t photons = 262144;  // paths to emit
    // The shard [path_begin, path_end) of those paths to trace (path_end 0: all of them); each
    // path is a pure function of its index, so shards concatenate to the whole run.
    std::uint64_t path_begin = 0, path_end = 0;
    std::uint32_t max_bounces = 4;
    std::uint32_t seed = 0;
};

struct ShotPhotons {
    PhotonHitsInfo info{};
    std::vector<PhotonHit> hits;
    std::uint64_t rays = 0;
};

// Throws std::invalid_argument when the scene has no light with power, for more than
// 2^32 - 1 photons, or for a path range outside 0 <= begin < end <= photons. `progress`
// receives the fraction done.
ShotPhotons shoot_photons(const GeometryView& g, const ShootOptions& options,
                          const std::function<void(double)>& progress = {});

}  // namespace kdpm
