#pragma once
// Ray origins leave a surface offset along its geometric normal, by a distance that scales with
// the scene so that a ray does not hit the surface it starts on.
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"

namespace kdpm {

// p moved by `offset` to the side of the unit geometric normal ng (above) or against it.
KDPM_HD KDPM_INLINE glm::vec3 offset_origin(const glm::vec3& p, const glm::vec3& ng, float offset, bool above) {
    return p + (above ? offset : -offset) * ng;
}

// The two scales in use; each is part of what its files and images are a function of, so
// they stay as they were chosen:
// photon paths: 1e-5 of the longest side of the scene bounds (at least 1e-6);
float photon_ray_offset(const GeometryInfo& info);
// camera paths and shadow rays: 2e-5 of the largest absolute coordinate of the bounds (at least 1).
float render_ray_offset(const GeometryInfo& info);

}  // namespace kdpm
