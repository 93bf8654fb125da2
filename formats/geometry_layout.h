#pragma once
// Records of the geometry kd-tree file (.kdg): written by kdpm-build-geometry, mapped in place
// by the runtime. Plain floats (no GLM) so the layout is exactly what SPEC.md says.
#include <cstdint>

#include "formats/kd_node.h"

namespace kdpm {

// Deepest geometry kd-tree a file may hold (inner nodes on a root-to-leaf path): the traversal
// keeps one stack entry per level. Builders stay below it; validators refuse deeper trees.
inline constexpr std::uint32_t kMaxKdTreeDepth = 64;

// Summary of the scene and tree; section geometry.info, one record.
struct GeometryInfo {
    float bounds_min[3];             // bounds of the triangles in the tree = the root cell
    std::uint32_t triangle_count;
    float bounds_max[3];
    std::uint32_t node_count;
    std::uint32_t leaf_index_count;
    std::uint32_t max_depth;         // inner nodes on the longest root-to-leaf path
    std::uint32_t default_photons;   // from the scene card
    std::uint32_t default_bounces;
    std::uint32_t default_k;
    std::uint32_t up_axis;           // 0, 1 or 2
    std::uint32_t reserved[2];
};
static_assert(sizeof(GeometryInfo) == 64);

// A triangle as the traversal reads it (Möller–Trumbore: one vertex and two edges).
struct TriangleRecord {
    float v0[3];
    std::uint32_t material;       // index into geometry.materials
    float e1[3];                  // v1 - v0
    std::uint32_t source_index;   // index of the triangle in the source mesh order
    float e2[3];                  // v2 - v0
    std::uint32_t flags;          // bit 0: has shading normals in geometry.normals
};
inline constexpr std::uint32_t kTriangleHasNormals = 1u;
static_assert(sizeof(TriangleRecord) == 48);

// Per-vertex shading normals of a triangle (same order as geometry.triangles).
struct TriangleNormals {
    float n[3][3];
};
static_assert(sizeof(TriangleNormals) == 36);

enum class MaterialKind : std::uint32_t { diffuse = 0, mirror = 1, glass = 2 };

struct MaterialRecord {
    float diffuse[3];        // albedo
    std::uint32_t kind;      // MaterialKind
    float specular[3];       // mirror reflectance
    float ior;               // glass index of refraction
    float transmission[3];   // glass transmittance
    std::uint32_t diffuse_texture;  // 0: none; else 1 + index into geometry.textures (the albedo)
    float emission[3];       // emitted radiance (MTL Ke, glTF emissive)
    float reserved1;
};
static_assert(sizeof(MaterialRecord) == 64);

// The index of refraction of glass that names none (an ior of 0 in a file, or 1 in an MTL).
inline constexpr float kDefaultGlassIor = 1.5f;

// Per-vertex texture coordinates of a triangle (same order as geometry.triangles; optional).
struct TriangleUVs {
    float uv[3][2];  // (u, v) at v0, v1, v2; v = 0 is the image's bottom row
};
static_assert(sizeof(TriangleUVs) == 24);

// A mip-mapped linear RGB texture: `levels` images from width x height down to 1 x 1, each
// half the previous (rounded down, at least 1), stored one after another from texel
// `first_texel` of geometry.texels, rows bottom to top (row 0 is v = 0).
struct TextureRecord {
    std::uint32_t width;
    std::uint32_t height;
    std::uint32_t levels;
    std::uint32_t reserved0;
    std::uint64_t first_texel;   // index into geometry.texels
    std::uint64_t texel_count;   // texels of all levels
};
static_assert(sizeof(TextureRecord) == 32);

// One linear RGB texel of geometry.texels.
struct Texel {
    float rgb[3];
};
static_assert(sizeof(Texel) == 12);

// Largest texture side the builder writes and the validator accepts.
inline constexpr std::uint32_t kMaxTextureSide = 16384;

// Mip levels of a full chain down to 1 x 1, and the size of one level.
constexpr std::uint32_t texture_level_count(std::uint32_t width, std::uint32_t height) {
    std::uint32_t levels = 1;
    while (width > 1 || height > 1) {
        width = width > 1 ? width / 2 : 1;
        height = height > 1 ? height / 2 : 1;
        ++levels;
    }
    return levels;
}
constexpr std::uint32_t texture_level_side(std::uint32_t side, std::uint32_t level) {
    const std::uint32_t s = level < 32 ? side >> level : 0;
    return s > 0 ? s : 1;
}

enum class LightShape : std::uint32_t { triangle = 0, parallelogram = 1 };

// An area light: p0 + u*e1 + v*e2 (triangle: u+v<=1), emitting one-sided along
// normalize(cross(e1, e2)) with constant radiance.
struct AreaLightRecord {
    float p0[3];
    std::uint32_t shape;          // LightShape
    float e1[3];
    std::uint32_t triangle;       // index into geometry.triangles, or 0xffffffff for card lights
    float e2[3];
    float area;
    float radiance[3];
    float power;                  // pi * area * mean(radiance): the emission sampling weight
};
static_assert(sizeof(AreaLightRecord) == 64);

struct CameraRecord {
    float eye[3];
    float vfov_degrees;
    float lookat[3];
    std::uint32_t width;
    float up[3];
    std::uint32_t height;
};
static_assert(sizeof(CameraRecord) == 48);

}  // namespace kdpm
