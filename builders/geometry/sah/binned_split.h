#pragma once
// Binned SAH split search for the large nodes of a fast build (Shevtsov et al. 2007; Hunt et al.
// 2006): each triangle's clipped bounds are counted into kBins bins per axis, in fixed-size chunks
// that run in parallel, and only the bin boundaries (plus the two planes that cut off empty space)
// are evaluated. Counts are integers and bounds are folded with min/max, so the result does not
// depend on the number of threads.
#include <cstdint>
#include <span>

#include "builders/geometry/sah/kd_build_params.h"
#include "formats/triangle_clip.h"

namespace kdpm {

inline constexpr int kBins = 64;

struct BinnedSplit {
    int axis = -1;  // -1: no candidate is cheaper than a leaf
    float pos = 0.0f;
    bool planar_left = true;
};

// `boxes`: the node's triangles' bounds clipped to `cell`.
BinnedSplit find_binned_split(std::span<const AxisBox> boxes, const AxisBox& cell, const KdBuildParams& params);

}  // namespace kdpm
