#include "runtime/shading/ray_offset.h"

#include <algorithm>
#include <cmath>

namespace kdpm {

float photon_ray_offset(const GeometryInfo& info) {
    float extent = 0.0f;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, info.bounds_max[a] - info.bounds_min[a]);
    return std::max(1e-5f * extent, 1e-6f);
}

float render_ray_offset(const GeometryInfo& info) {
    float extent = 1.0f;
    for (int a = 0; a < 3; ++a)
        extent = std::max({extent, std::fabs(info.bounds_min[a]), std::fabs(info.bounds_max[a])});
    return 2e-5f * extent;
}

}  // namespace kdpm
