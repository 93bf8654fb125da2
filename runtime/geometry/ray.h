#pragma once
// A ray segment and the result of a closest-hit query, shared by every kernel that traces
// against the geometry kd-tree.
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"

namespace kdpm {

// Points origin + t * direction for t in the open interval (tmin, tmax). The direction need not
// be normalised; t is measured in units of its length.
struct Ray {
    glm::vec3 origin;
    float tmin;
    glm::vec3 direction;
    float tmax;
};

inline constexpr std::uint32_t kNoHit = 0xffffffffu;
// Hit::instance of a scene without instances (its own triangles were hit).
inline constexpr std::uint32_t kNoInstance = 0xffffffffu;

struct Hit {
    float t;                // ray parameter of the hit
    std::uint32_t triangle; // index into geometry.triangles (of the instance's object), kNoHit on a miss
    float u, v;             // barycentrics of v1 and v2: p = v0 + u * e1 + v * e2
    std::uint32_t instance = kNoInstance;  // index into GeometryView::instances when the scene has them

    KDPM_HD bool found() const { return triangle != kNoHit; }
};

KDPM_HD KDPM_INLINE Hit miss(float tmax) { return Hit{tmax, kNoHit, 0.0f, 0.0f}; }

}  // namespace kdpm
