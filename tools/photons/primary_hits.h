#pragma once
// The camera's primary hit points (one ray through each pixel centre of the .kdg camera), the
// query points of the photon gather benchmark.
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/geometry/geometry_file.h"

namespace kdpm::photon_tools {

struct SurfacePoint {
    glm::vec3 position;
    glm::vec3 normal;  // geometric, facing the camera
};

// Pixels whose ray hits nothing are left out; order is row-major over the hits.
std::vector<SurfacePoint> primary_hits(const GeometryFile& geometry, std::uint32_t width, std::uint32_t height);

}  // namespace kdpm::photon_tools
