#pragma once
// Section ids of every kdpm file kind, in one place so that tools can name sections they print.
// Ids are unique across kinds; a reader skips ids it does not know (newer minor versions).
#include <cstdint>
#include <string_view>

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

// photon hits (.kdph)
inline constexpr std::uint32_t hits_info = 0x200;      // PhotonHitsInfo, one record
inline constexpr std::uint32_t hits_photons = 0x201;   // PhotonHit[]

// photon kd-tree (.kdp)
inline constexpr std::uint32_t ptree_info = 0x300;     // PhotonTreeInfo, one record
inline constexpr std::uint32_t ptree_nodes = 0x301;    // KdNode[]
inline constexpr std::uint32_t ptree_pos_x = 0x302;    // f32[] positions in leaf order
inline constexpr std::uint32_t ptree_pos_y = 0x303;
inline constexpr std::uint32_t ptree_pos_z = 0x304;
inline constexpr std::uint32_t ptree_power = 0x305;    // u32 RGBE power, one per photon
inline constexpr std::uint32_t ptree_direction = 0x306;  // PackedPhotonDirections[] (octahedral)
inline constexpr std::uint32_t ptree_flags = 0x307;    // u32 flags per photon (caustic, bounce)
// the caustic map of the same .kdp: the same fields at 0x310 + field (formats/photon_layout.h)
inline constexpr std::uint32_t ptree_caustic_info = 0x310;
inline constexpr std::uint32_t ptree_caustic_nodes = 0x311;
inline constexpr std::uint32_t ptree_caustic_pos_x = 0x312;
inline constexpr std::uint32_t ptree_caustic_pos_y = 0x313;
inline constexpr std::uint32_t ptree_caustic_pos_z = 0x314;
inline constexpr std::uint32_t ptree_caustic_power = 0x315;
inline constexpr std::uint32_t ptree_caustic_direction = 0x316;
inline constexpr std::uint32_t ptree_caustic_flags = 0x317;

// test containers
inline constexpr std::uint32_t test_first = 0xF00;

std::string_view name(std::uint32_t id);  // "" when unknown

}  // namespace kdpm::section
