#include "builders/geometry/scene_import.h"

#include <assimp/Importer.hpp>
#include <assimp/ObjMaterial.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>

#include "formats/format_error.h"
#include "formats/metadata.h"

namespace kdpm {

namespace {

void set3(float (&dst)[3], const aiColor3D& c) {
    dst[0] = c.r;
    dst[1] = c.g;
    dst[2] = c.b;
}

bool is_black(const aiColor3D& c) { return !(c.r > 0.0f || c.g > 0.0f || c.b > 0.0f); }

// OBJ/MTL: illum 3 (or Ks with black Kd) is a mirror, illum 4/6/7/9 with Tf or Ni a glass.
// glTF: transmission factor makes a glass. Textures are not used: Kd is the albedo.
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
        if (r.ior == 1.0f) r.ior = 1.5f;
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

    void node(const aiNode& n, const aiMatrix4x4& parent) {
        const aiMatrix4x4 world = parent * n.mTransformation;
        aiMatrix3x3 normal_matrix(world);
        normal_matrix.Inverse().Transpose();
        for (unsigned i = 0; i < n.mNumMeshes; ++i) mesh(*ai.mMeshes[n.mMeshes[i]], world, normal_matrix);
        for (unsigned i = 0; i < n.mNumChildren; ++i) node(*n.mChildren[i], world);
    }

    void mesh(const aiMesh& m, const aiMatrix4x4& world, const aiMatrix3x3& normal_matrix) {
        const std::uint32_t material = std::min(m.mMaterialIndex, static_cast<unsigned>(scene.materials.size() - 1));
        for (unsigned f = 0; f < m.mNumFaces; ++f) {
            const aiFace& face = m.mFaces[f];
            if (face.mNumIndices != 3) continue;  // points and lines
            float p[3][3];
            TriangleNormals normals{};
            for (int k = 0; k < 3; ++k) {
                const unsigned idx = face.mIndices[k];
                const aiVector3D v = world * m.mVertices[idx];
                p[k][0] = v.x, p[k][1] = v.y, p[k][2] = v.z;
                if (m.HasNormals()) {
                    aiVector3D nn = normal_matrix * m.mNormals[idx];
                    nn.Normalize();
                    normals.n[k][0] = nn.x, normals.n[k][1] = nn.y, normals.n[k][2] = nn.z;
                }
            }
            const auto index = static_cast<std::uint32_t>(scene.triangles.size());
            TriangleRecord t = make_triangle(p[0], p[1], p[2], material, index);
            if (m.HasNormals()) t.flags |= kTriangleHasNormals;
            scene.triangles.push_back(t);
            scene.normals.push_back(normals);
        }
    }
};

}  // namespace

Scene import_mesh(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw FormatError(path.string() + ": no such mesh file");
    Assimp::Importer importer;
    // Triangulate only: no vertex joining, mesh merging or sorting, so source order survives.
    const aiScene* ai = importer.ReadFile(path.string(), aiProcess_Triangulate);
    if (!ai || !ai->mRootNode || (ai->mFlags & AI_SCENE_FLAGS_INCOMPLETE)) {
        std::string why = importer.GetErrorString();
        std::replace(why.begin(), why.end(), '\n', ' ');
        throw FormatError(path.string() + ": cannot read mesh" + (why.empty() ? "" : ": " + why));
    }
    Scene scene;
    for (unsigned i = 0; i < ai->mNumMaterials; ++i) scene.materials.push_back(convert_material(*ai->mMaterials[i]));
    if (scene.materials.empty()) scene.materials.push_back(MaterialRecord{{0.8f, 0.8f, 0.8f}, 0, {}, 1.0f, {}, 0, {}, 0});
    Walker{*ai, scene}.node(*ai->mRootNode, aiMatrix4x4());
    if (scene.triangles.empty()) throw FormatError(path.string() + ": the mesh has no triangles");
    const bool any_normals = std::any_of(scene.triangles.begin(), scene.triangles.end(),
                                         [](const TriangleRecord& t) { return t.flags & kTriangleHasNormals; });
    if (!any_normals) scene.normals.clear();
    add_emissive_triangle_lights(scene);
    scene.source_name = path.filename().string();
    scene.source_hash = hash_file(path.string());
    return scene;
}

}  // namespace kdpm
