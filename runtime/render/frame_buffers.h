#pragma once
// The per-frame arrays the passes read and write, as raw pointers (host or device memory).
// Every pass writes only the slots of its own work item.
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"

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
    DiffuseVertex* vertices = nullptr;       // kMaxDiffuseVertices per pixel, at vertex_slot
    glm::vec3* gathered = nullptr;           // per vertex slot: radiance from the photon maps
    glm::vec3* accum = nullptr;              // per pixel: sum over samples
    // AOVs of the first sample's first hit; each may be null when not asked for.
    float* depth = nullptr;
    glm::vec3* normal = nullptr;
    glm::vec3* position = nullptr;
    std::int32_t* triangle = nullptr;

    // Where a pixel's vertex i (< kMaxDiffuseVertices) lives in vertices and gathered: all first
    // vertices, then all second ones, and so on. Nearly every pixel has just a first vertex, and
    // neighbouring pixels' then share cache lines; with a pixel's slots together, each pixel's
    // first vertex would be a cache miss of its own.
    KDPM_HD std::uint64_t vertex_slot(std::uint64_t pixel, std::uint32_t i) const {
        return static_cast<std::uint64_t>(i) * pixel_count() + pixel;
    }
    KDPM_HD std::uint64_t slot_pixel(std::uint64_t slot) const { return slot % pixel_count(); }
    KDPM_HD std::uint32_t slot_vertex(std::uint64_t slot) const {
        return static_cast<std::uint32_t>(slot / pixel_count());
    }
    KDPM_HD std::uint64_t pixel_count() const { return static_cast<std::uint64_t>(width) * height; }
};

}  // namespace kdpm
