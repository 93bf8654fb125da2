#pragma once
// A scene ready to be turned into a .kdg file: triangles in source order with their materials,
// optional shading normals, area lights, the camera and the rendering defaults of the card.
#include <cstdint>
#include <string>
#include <vector>

#include "formats/geometry_layout.h"

namespace kdpm {

struct Scene {
    std::vector<TriangleRecord> triangles;   // source order; source_index = position
    std::vector<TriangleNormals> normals;    // empty, or one per triangle
    std::vector<MaterialRecord> materials;
    std::vector<TriangleUVs> uvs;            // empty, or one per triangle
    std::vector<std::string> texture_paths;  // empty, or one per material: its diffuse texture file ("" none)
    std::vector<TextureRecord> textures;     // read by load_textures(); materials point at them
    std::vector<Texel> texels;
    std::vector<std::string> warnings;       // one line each, for the tool to print
    std::vector<AreaLightRecord> lights;
    CameraRecord camera{};
    bool has_camera = false;                 // false: frame_camera() picks one from the bounds
    std::uint32_t photons = 262144;
    std::uint32_t bounces = 4;
    std::uint32_t k = 64;
    std::uint32_t up_axis = 1;
    std::string source_name;                 // mesh file name, for the metadata
    std::string source_hash;                 // kdpm::hash_file of the mesh
};

// A triangle record from three vertices.
TriangleRecord make_triangle(const float (&a)[3], const float (&b)[3], const float (&c)[3], std::uint32_t material,
                             std::uint32_t source_index);

// A parallelogram light p0 + u e1 + v e2 emitting along cross(e1, e2) (scene card lights).
AreaLightRecord make_parallelogram_light(const float (&p0)[3], const float (&e1)[3], const float (&e2)[3],
                                         const float (&radiance)[3]);

// Appends one triangle light per usable triangle whose material emits.
void add_emissive_triangle_lights(Scene& scene);

// Sets a camera that sees the whole scene from the front along the up axis (bare meshes).
void frame_camera(Scene& scene);
// The same camera for a box (a scene of instances: the placed objects' world box).
void frame_camera_on(Scene& scene, const float (&lo)[3], const float (&hi)[3]);

// Surface areas (the SAH cost, light areas) are products of two extents: beyond this coordinate
// they overflow a float and every cost turns inf or NaN.
inline constexpr float kMaxSceneCoordinate = 1e18f;
// Throws FormatError when a usable triangle reaches past kMaxSceneCoordinate.
void check_scene_extent(const Scene& scene);

}  // namespace kdpm
