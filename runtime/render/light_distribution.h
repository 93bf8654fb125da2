#pragma once
// Host side of light selection: the cumulative power of the scene's lights, built once per
// scene (then used in place on the CPU, or uploaded once for CUDA).
#include <vector>

#include "runtime/geometry/geometry_view.h"

namespace kdpm {

// cdf[i] = (power[0] + ... + power[i]) / total, the last entry exactly 1. Empty when no light
// has positive, finite power.
std::vector<float> light_power_cdf(const GeometryView& geometry);

}  // namespace kdpm
