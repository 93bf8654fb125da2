#include "builders/geometry/import/scene_import.h"

#include <assimp/Importer.hpp>
#include <assimp/ObjMaterial.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "builders/geometry/import/mesh_nesting.h"
#include "builders/geometry/sah/large_stack.h"
#include "formats/format_error.h"
#include "formats/metadata.h"

namespace kdpm {

namespace {

// Colours reach the kernels as they are: a non-finite one is refused, a negative one is black.
void set3(float (&dst)[3], const aiColor3D& c) {
    const float v[3] = {c.r, c.g, c.b};
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(v[i])) throw FormatError("a material colour is not finite");
        dst[i] = std::max(v[i], 0.0f);
    }
}

bool is_black(const aiColor3D& c) { return !(c.r > 0.0f || c.g > 0.0f || c.b > 0.0f); }

// OBJ/MTL: illum 3 (or Ks with black Kd) is a mirror, illum 4/6/7/9 with Tf or Ni a glass.
// glTF: transmission factor makes a glass. A diffuse texture, when one is read, replaces Kd.
// The material's diffuse (OBJ map_Kd) or base colour (glTF) texture file, resolved against the
// mesh's folder; "" when it has none or the texture is embedded in the mesh (not supported: the
// builder warns and uses the colour).
std::string diffuse_texture_path(const aiMaterial& m, const std::filesystem::path& mesh_dir, std::vector<std::string>& warnings) {
    aiString name;
    if (m.GetTexture(aiTextureType_DIFFUSE, 0, &name) != AI_SUCCESS &&
        m.GetTexture(aiTextureType_BASE_COLOR, 0, &name) != AI_SUCCESS)
        return "";
    std::string file(name.C_Str());
    if (file.empty()) return "";
    if (file[0] == '*') {
        warnings.push_back("material " + std::string(m.GetName().C_Str()) +
                           ": embedded textures are not read; using its diffuse colour");
        return "";
    }
    std::replace(file.begin(), file.end(), '\\', '/');  // MTL files written on Windows
    const std::filesystem::path p(file);
    return (p.is_absolute() || mesh_dir.empty() ? p : mesh_dir / p).lexically_normal().string();
}

MaterialRecord convert_material(const aiMaterial& m) {
    MaterialRecord r{};
    aiColor3D kd(0.8f, 0.8f, 0.8f), ks(0, 0, 0), ke(0, 0, 0), tf(0, 0, 0);
    m.Get(AI_MATKEY_COLOR_DIFFUSE, kd);
    aiColor4D base;
    if (m.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) kd = aiColor3D(base.r, base.g, base.b);
    m.Get(AI_MATKEY_COLOR_SPECULAR, ks);
    m.Get(AI_MATKEY_COLOR_EMISSIVE, ke);
    const bool has_tf = m.Get(AI_MATKEY_COLOR_TRANSPARENT, tf) == AI_SUCCESS;
    float ni = 1.0f, emissive_intensity = 1.0f, transmission = 0.0f;
    m.Get(AI_MATKEY_REFRACTI, ni);
    if (m.Get(AI_MATKEY_EMISSIVE_INTENSITY, emissive_intensity) == AI_SUCCESS)
        ke = aiColor3D(ke.r * emissive_intensity, ke.g * emissive_intensity, ke.b * emissive_intensity);
    m.Get(AI_MATKEY_TRANSMISSION_FACTOR, transmission);
    int illum = -1;
    m.Get(AI_MATKEY_OBJ_ILLUM, illum);

    set3(r.diffuse, kd);
    set3(r.specular, ks);
    set3(r.emission, ke);
    r.ior = std::isfinite(ni) && ni > 0.0f ? ni : 1.0f;
    const bool glass = illum == 4 || illum == 6 || illum == 7 || illum == 9 || transmission > 0.0f;
    const bool mirror = !glass && (illum == 3 || illum == 5 || (is_black(kd) && !is_black(ks) && illum != 2 && illum != 1));
    if (glass) {
        r.kind = static_cast<std::uint32_t>(MaterialKind::glass);
        if (has_tf && !is_black(tf)) set3(r.transmission, tf);
        else if (transmission > 0.0f) set3(r.transmission, aiColor3D(transmission, transmission, transmission));
        else set3(r.transmission, aiColor3D(1, 1, 1));
        if (r.ior == 1.0f) r.ior = kDefaultGlassIor;
    } else if (mirror) {
        r.kind = static_cast<std::uint32_t>(MaterialKind::mirror);
        if (is_black(ks)) set3(r.specular, aiColor3D(1, 1, 1));
    } else {
        r.kind = static_cast<std::uint32_t>(MaterialKind::diffuse);
    }
    return r;
}

struct Walker {
    const aiScene& ai;
    Scene& scene;

    // Iterative, in source order: a node hierarchy thousands of levels deep needs no stack.
    void walk(const aiNode& root) {
        std::vector<std::pair<const aiNode*, aiMatrix4x4>> pending{{&root, aiMatrix4x4()}};
        while (!pending.empty()) {
            const auto [n, parent] = pending.back();
            pending.pop_back();
            const aiMatrix4x4 world = parent * n->mTransformation;
            aiMatrix3x3 normal_matrix(world);
            normal_matrix.Inverse().Transpose();
            for (unsigned i = 0; i < n->mNumMeshes; ++i) {
                if (n->mMeshes[i] >= ai.mNumMeshes) throw FormatError("a node names a mesh that does not exist");
                mesh(*ai.mMeshes[n->mMeshes[i]], world, normal_matrix);
            }
            for (unsigned i = n->mNumChildren; i-- > 0;) pending.push_back({n->mChildren[i], world});
        }
    }

    void mesh(const aiMesh& m, const aiMatrix4x4& world, const aiMatrix3x3& normal_matrix) {
        const std::uint32_t material = std::min(m.mMaterialIndex, static_cast<unsigned>(scene.materials.size() - 1));
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines
            float p[3][3];
            TriangleNormals normals{};
            TriangleUVs uvs{};
            bool usable_normals = m.HasNormals();
            for (int k = 0; k < 3; ++k) {
                const unsigned idx = face.mIndices[k];
                // Importers pass face indices through unchecked (PLY does).
                if (idx >= m.mNumVertices)
                    throw FormatError("face " + std::to_string(f) + " names vertex " + std::to_string(idx) + " of " +
                                      std::to_string(m.mNumVertices));
                const aiVector3D v = world * m.mVertices[idx];
                p[k][0] = v.x, p[k][1] = v.y, p[k][2] = v.z;
                if (usable_normals) {
                    aiVector3D nn = normal_matrix * m.mNormals[idx];
                    nn.Normalize();
                    // A zero or non-finite normal would shade with NaN: the triangle uses its own.
                    if (!std::isfinite(nn.x + nn.y + nn.z) || nn.SquareLength() < 0.5f) usable_normals = false;
                    normals.n[k][0] = nn.x, normals.n[k][1] = nn.y, normals.n[k][2] = nn.z;
                }
                if (m.HasTextureCoords(0)) {
                    const aiVector3D t = m.mTextureCoords[0][idx];
                    // A non-finite coordinate has no texel: it reads the texture's corner.
                    uvs.uv[k][0] = std::isfinite(t.x) ? t.x : 0.0f;
                    uvs.uv[k][1] = std::isfinite(t.y) ? t.y : 0.0f;
                    has_uvs = true;
                }
            }
            const auto index = static_cast<std::uint32_t>(scene.triangles.size());
            TriangleRecord t = make_triangle(p[0], p[1], p[2], material, index);
            if (usable_normals) t.flags |= kTriangleHasNormals;
            scene.triangles.push_back(t);
            scene.normals.push_back(normals);
            scene.uvs.push_back(uvs);
        }
    }

    bool has_uvs = false;
};

// A mesh path must name a regular, non-empty file: say which it is not (a device such as
// /dev/zero would be read forever, a FIFO would block).
void check_mesh_file(const std::filesystem::path& path) {
    if (path.empty() || path.filename().empty()) throw FormatError("the mesh path is empty");
    struct stat st{};
    if (::stat(path.c_str(), &st) != 0)
        throw FormatError(path.string() + ": " + (errno == ENOENT ? "no such mesh file" : std::strerror(errno)));
    if (S_ISDIR(st.st_mode)) throw FormatError(path.string() + ": the mesh path is a folder");
    if (!S_ISREG(st.st_mode))
        throw FormatError(path.string() + ": the mesh is not a regular file (a device, FIFO or socket)");
    if (st.st_size == 0) throw FormatError(path.string() + ": the mesh file is empty");
    check_mesh_nesting(path);
}

}  // namespace

namespace {

// The scene of an Assimp import (null when it failed): materials, triangles in source order,
// emissive triangles as lights. `name` prefixes every message.
Scene convert_scene(const Assimp::Importer& importer, const aiScene* ai, const std::string& name,
                    const std::filesystem::path& mesh_dir) {
    if (!ai || !ai->mRootNode || (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        std::string why = importer.GetErrorString();
        std::replace(why.begin(), why.end(), '\n', ' ');
        throw FormatError(name + ": cannot read mesh" + (why.empty() ? "" : ": " + why));
    }
    Scene scene;
    try {
        for (unsigned i = 0; i < ai->mNumMaterials; ++i) {
            scene.materials.push_back(convert_material(*ai->mMaterials[i]));
            scene.texture_paths.push_back(diffuse_texture_path(*ai->mMaterials[i], mesh_dir, scene.warnings));
        }
        if (scene.materials.empty()) scene.materials.push_back(MaterialRecord{{0.8f, 0.8f, 0.8f}, 0, {}, 1.0f, {}, 0, {}, 0});
        if (std::all_of(scene.texture_paths.begin(), scene.texture_paths.end(), [](const std::string& p) { return p.empty(); }))
            scene.texture_paths.clear();
        Walker walker{*ai, scene};
        walker.walk(*ai->mRootNode);
        if (!walker.has_uvs) scene.uvs.clear();
    } catch (const FormatError& e) {
        throw FormatError(name + ": " + e.what());
    }
    if (scene.triangles.empty()) throw FormatError(name + ": the mesh has no triangles");
    const bool any_normals = std::any_of(scene.triangles.begin(), scene.triangles.end(),
                                         [](const TriangleRecord& t) { return t.flags & kTriangleHasNormals; });
    if (!any_normals) scene.normals.clear();
    add_emissive_triangle_lights(scene);
    return scene;
}

}  // namespace

Scene import_mesh(const std::filesystem::path& path) {
    check_mesh_file(path);
    Assimp::Importer importer;
    // Triangulate only: no vertex joining, mesh merging or sorting, so source order survives.
    // On a large stack: Assimp's importers recurse once per nesting level of the file.
    const aiScene* ai = nullptr;
    run_with_large_stack([&] { ai = importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_ValidateDataStructure); });
    Scene scene = convert_scene(importer, ai, path.string(), path.parent_path());
    scene.source_name = path.filename().string();
    scene.source_hash = hash_file(path.string());
    return scene;
}

Scene import_mesh_from_memory(std::string_view bytes, const std::string& extension, const std::string& name) {
    if (bytes.empty()) throw FormatError(name + ": the mesh file is empty");
    check_mesh_nesting(bytes, extension, name);
    Assimp::Importer importer;
    const aiScene* ai = nullptr;
    // 64 MiB: enough for the nesting the pre-check lets through, and cheap to create per call.
    run_with_large_stack([&] {
        ai = importer.ReadFileFromMemory(bytes.data(), bytes.size(), aiProcess_Triangulate | aiProcess_ValidateDataStructure, extension.c_str());
    }, std::size_t{64} << 20);
    Scene scene = convert_scene(importer, ai, name, {});
    scene.source_name = name;
    return scene;
}

}  // namespace kdpm
