#pragma once
// Everything a kernel needs from a .kdg file, as plain pointers and counts. The arrays live in
// the memory-mapped file on the CPU (GeometryFile) or in device memory after one upload each.
#include <cstdint>

#include "formats/geometry_layout.h"
#include "formats/kd_node.h"
#include "formats/wide_layout.h"
#include "runtime/geometry/instance_view.h"

namespace kdpm {

// The traversal stack holds one entry per tree level; builders and the validator keep trees
// at most this deep.
inline constexpr std::uint32_t kMaxKdDepth = kMaxKdTreeDepth;

struct GeometryView {
    const KdNode* nodes = nullptr;
    std::uint32_t node_count = 0;
    const WideNode* wide = nullptr;            // the wide tree (format 1.2), nullptr when absent
    std::uint32_t wide_node_count = 0;
    const std::uint32_t* leaf_indices = nullptr;
    std::uint32_t leaf_index_count = 0;
    const TriangleRecord* triangles = nullptr;
    std::uint32_t triangle_count = 0;
    const TriangleNormals* normals = nullptr;  // nullptr when the file has no shading normals
    const MaterialRecord* materials = nullptr;
    std::uint32_t material_count = 0;
    const AreaLightRecord* lights = nullptr;
    std::uint32_t light_count = 0;
    const TriangleUVs* uvs = nullptr;          // nullptr when the file has no texture coordinates
    const TextureRecord* textures = nullptr;   // MaterialRecord::diffuse_texture - 1 indexes these
    std::uint32_t texture_count = 0;
    const Texel* texels = nullptr;
    std::uint64_t texel_count = 0;
    GeometryInfo info{};  // a copy: bounds, counts and scene defaults
    // A scene of instances (format 1.3) has no triangles of its own: rays walk the instance BVH
    // into the objects' views (which have no instances themselves). Lights are in world space.
    const GeometryView* objects = nullptr;
    std::uint32_t object_count = 0;
    const InstancePlacement* instances = nullptr;
    std::uint32_t instance_count = 0;
    const InstanceNode* instance_nodes = nullptr;
    std::uint32_t instance_node_count = 0;
};

}  // namespace kdpm
