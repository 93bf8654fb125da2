#pragma once
// The camera's primary hit points (one ray through each pixel centre of the .kdg camera), the
// query points of the photon gather benchmark.
#include <cstdint>
#include <vector>

#include "runtime/geometry/geometry_file.h"
#include "runtime/shading/surface_point.h"

namespace kdpm::photon_tools {

// Pixels whose ray hits nothing are left out; order is row-major over the hits.
std::vector<SurfacePoint> primary_hits(const GeometryFile& geometry, std::uint32_t width, std::uint32_t height);

}  // namespace kdpm::photon_tools
