#pragma once
// Section ids of every kdpm file kind, in one place so that tools can name sections they print.
// Ids are unique across kinds; a reader skips ids it does not know (newer minor versions).
#include <cstdint>
#include <string>

namespace kdpm::section {

inline constexpr std::uint32_t metadata = 1;           // cereal JSON text, every kind

// geometry kd-tree (.kdg)
inline constexpr std::uint32_t geo_info = 0x100;       // GeometryInfo, one record
inline constexpr std::uint32_t geo_nodes = 0x101;      // KdNode[]
inline constexpr std::uint32_t geo_leaf_indices = 0x102;  // u32[] triangle indices of the leaves
inline constexpr std::uint32_t geo_triangles = 0x103;  // TriangleRecord[] (vertex + edges)
inline constexpr std::uint32_t geo_normals = 0x104;    // TriangleNormals[] shading normals
inline constexpr std::uint32_t geo_materials = 0x105;  // MaterialRecord[]
inline constexpr std::uint32_t geo_lights = 0x106;     // AreaLightRecord[]
inline constexpr std::uint32_t geo_camera = 0x107;     // CameraRecord, one record
inline constexpr std::uint32_t geo_uvs = 0x108;        // TriangleUVs[] texture coordinates (1.1)
inline constexpr std::uint32_t geo_textures = 0x109;   // TextureRecord[] mip-mapped diffuse textures (1.1)
inline constexpr std::uint32_t geo_texels = 0x10A;     // Texel[] of every texture's levels (1.1)
inline constexpr std::uint32_t geo_wide = 0x10B;       // WideNode[] the kd-tree collapsed to 8-wide nodes (1.2)
inline constexpr std::uint32_t geo_objects = 0x10C;    // ObjectReference[] object files a scene places (1.3)
inline constexpr std::uint32_t geo_instances = 0x10D;  // InstanceRecord[] placements of those objects (1.3)

// photon hits (.kdph)
inline constexpr std::uint32_t hits_info = 0x200;      // PhotonHitsInfo, one record
inline constexpr std::uint32_t hits_photons = 0x201;   // PhotonHit[]

// photon kd-tree (.kdp): photon_tree_section(map, field) in formats/photon_layout.h, the only
// definition of those ids (0x300 + 0x10 * map + field); name() derives their names from it.

// test containers
inline constexpr std::uint32_t test_first = 0xF00;

std::string name(std::uint32_t id);  // "" when unknown

}  // namespace kdpm::section
