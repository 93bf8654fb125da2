#pragma once
// The driver of the shooting kernel on either backend: runs trace_photon_path for every path in
// batches (shoot_loop.h: each path writes only its own max_bounces + 1 slots, or on the CPU its
// photons are tagged with their path and place), then puts the photons in path order, so the
// hits are identical whatever the thread count.
//
// CPU and CUDA: the CUDA kernels are compiled with --fmad=false (no fused multiply-add
// contraction, which the host compiler does not do either), and +, -, *, / and sqrt are
// correctly rounded on both sides, so ray/triangle hits and the kd-tree walk agree bit for bit.
// The one place the two can still differ is the emission and bounce directions: cosf/sinf in
// cosine_direction come from glibc on the host and CUDA's libdevice on the GPU, which may round
// differently in the last place. Such a photon's later hit can move by a few ulps, and, rarely,
// a grazing path can hit a different triangle. The two backends' files are therefore compared
// hit by hit within a tolerance (tests/gpu), not byte for byte.
#include <cstdint>
#include <functional>
#include <vector>

#include "formats/photon_layout.h"
#include "runtime/backend/backend_kind.h"
#include "runtime/geometry/geometry_view.h"

namespace kdpm {

struct ShootOptions {
    std::uint64_t photons = 262144;  // paths to emit
    // The shard [path_begin, path_end) of those paths to trace (path_end 0: all of them); each
    // path is a pure function of its index, so shards concatenate to the whole run.
    std::uint64_t path_begin = 0, path_end = 0;
    std::uint32_t max_bounces = 4;
    std::uint32_t seed = 0;
    BackendKind backend = BackendKind::cpu;  // CUDA: throws std::runtime_error without a device
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
