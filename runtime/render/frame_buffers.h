#pragma once
// The per-frame arrays the passes read and write, as raw pointers (host or device memory).
// Every pass writes only the slots of its own work item.
#include <cstdint>

#include <glm/vec3.hpp>

namespace kdpm {

// Diffuse surfaces a camera sample reaches directly or through mirrors and glass. Glass splits
// a path in two, so a sample may end on several; beyond this many the rest are dropped.
inline constexpr std::uint32_t kMaxDiffuseVertices = 4;

// A diffuse point to shade, with the product of the specular reflectances on the way to it.
struct DiffuseVertex {
    glm::vec3 position;
    glm::vec3 shading_normal;    // unit, on the side the ray arrived from
    glm::vec3 geometric_normal;  // unit, on the side the ray arrived from (ray offsets)
    glm::vec3 albedo;
    glm::vec3 throughput;
};

struct FrameBuffersView {
    std::uint32_t width = 0, height = 0;
    glm::vec3* emitted = nullptr;            // per pixel: emitters seen by this sample's rays
    std::uint32_t* vertex_count = nullptr;   // per pixel
    DiffuseVertex* vertices = nullptr;       // per pixel * kMaxDiffuseVertices
    glm::vec3* gathered = nullptr;           // per vertex: radiance from the photon maps
    glm::vec3* accum = nullptr;              // per pixel: sum over samples
    // AOVs of the first sample's first hit; each may be null when not asked for.
    float* depth = nullptr;
    glm::vec3* normal = nullptr;
    glm::vec3* position = nullptr;
    std::int32_t* triangle = nullptr;
};

}  // namespace kdpm
