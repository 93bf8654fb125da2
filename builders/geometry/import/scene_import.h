#pragma once
// Mesh import through Assimp: any format it reads (OBJ/MTL, glTF, PLY, FBX, ...). Triangles keep
// the order Assimp delivers them in (meshes in node order, faces in order, polygons fanned);
// nothing is joined, merged or reordered, and degenerate triangles are kept as records (the
// tree leaves them out). Materials become MaterialRecords; emissive triangles become lights.
#include <filesystem>
#include <string>
#include <string_view>

#include "builders/geometry/scene.h"

namespace kdpm {

// Throws FormatError with a one-line reason when the file cannot be read or holds no mesh.
// The camera is left unset (has_camera false) and the up axis at +Y.
Scene import_mesh(const std::filesystem::path& path);

// The same from bytes in memory (the fuzzer); `extension` ("obj", "ply", "gltf", ...) tells
// Assimp the format, `name` prefixes messages. No source hash is recorded.
Scene import_mesh_from_memory(std::string_view bytes, const std::string& extension, const std::string& name);

}  // namespace kdpm
