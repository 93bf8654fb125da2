#include "builders/geometry/geometry_file_builder.h"

#include <cstdio>
#include <string>

#include "builders/geometry/sah/sah_kd_builder.h"
#include "builders/geometry/wide/wide_tree_builder.h"
#include "formats/format_error.h"
#include "formats/metadata.h"
#include "formats/section_ids.h"

namespace kdpm {

namespace {

std::string text(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

}  // namespace

GeometryBuild build_geometry_file(const Scene& scene, const KdBuildParams& params,
                                  const std::function<void(double)>& progress) {
    if (!scene.normals.empty() && scene.normals.size() != scene.triangles.size())
        throw FormatError("scene has " + std::to_string(scene.normals.size()) + " normal records for " +
                          std::to_string(scene.triangles.size()) + " triangles");
    if (!scene.uvs.empty() && scene.uvs.size() != scene.triangles.size())
        throw FormatError("scene has " + std::to_string(scene.uvs.size()) + " texture coordinate records for " +
                          std::to_string(scene.triangles.size()) + " triangles");
    if (!scene.textures.empty() && scene.uvs.empty()) throw FormatError("scene has textures but no texture coordinates");
    for (const MaterialRecord& m : scene.materials)
        if (m.diffuse_texture > scene.textures.size()) throw FormatError("material texture index out of range");
    if (scene.triangles.size() > 0xfffffffeu) throw FormatError("too many triangles");
    for (const TriangleRecord& t : scene.triangles)
        if (t.material >= scene.materials.size()) throw FormatError("triangle material index out of range");

    check_scene_extent(scene);
    const KdTree tree = build_sah_kd_tree(scene.triangles, params, progress);
    // assemble_geometry_file frames a camera when the scene has none.
    return GeometryBuild{assemble_geometry_file(scene, tree, params), tree.stats, tree.repeated_triangles};
}

ContainerWriter assemble_geometry_file(const Scene& input, const KdTree& tree, const KdBuildParams& params) {
    const Scene* scene = &input;
    Scene framed;
    if (!input.has_camera) {
        framed = input;
        frame_camera(framed);
        scene = &framed;
    }

    GeometryInfo info{};
    for (int a = 0; a < 3; ++a) info.bounds_min[a] = tree.bounds.lo[a], info.bounds_max[a] = tree.bounds.hi[a];
    info.triangle_count = static_cast<std::uint32_t>(scene->triangles.size());
    info.node_count = static_cast<std::uint32_t>(tree.nodes.size());
    info.leaf_index_count = static_cast<std::uint32_t>(tree.leaf_indices.size());
    info.max_depth = tree.stats.max_depth;
    info.default_photons = scene->photons;
    info.default_bounces = scene->bounces;
    info.default_k = scene->k;
    info.up_axis = scene->up_axis;

    Metadata meta;
    meta.tool = "kdpm-build-geometry";
    meta.tool_version = kdpm_version();
    meta.source_path = scene->source_name;
    meta.source_hash = scene->source_hash;
    meta.parameters["traversal_cost"] = text(params.traversal_cost);
    meta.parameters["intersection_cost"] = text(params.intersection_cost);
    meta.parameters["empty_bonus"] = text(params.empty_bonus);
    meta.parameters["max_depth"] = std::to_string(tree.limits.max_depth);
    meta.parameters["small_node_depth"] = std::to_string(tree.limits.small_depth);
    meta.parameters["small_node_triangles"] = std::to_string(tree.limits.small_triangles);
    meta.parameters["leaf_size"] = std::to_string(params.leaf_size);
    meta.parameters["quality"] = std::string(quality_name(params.quality));
    if (params.quality == KdBuildQuality::fast) {
        meta.parameters["exact_below"] = std::to_string(params.exact_below);
        meta.parameters["clip_below"] = std::to_string(params.clip_below);
    }
    const KdTreeStats& s = tree.stats;
    meta.statistics["triangles"] = static_cast<double>(scene->triangles.size());
    meta.statistics["nodes"] = static_cast<double>(s.nodes);
    meta.statistics["leaves"] = static_cast<double>(s.leaves);
    meta.statistics["empty_leaves"] = static_cast<double>(s.empty_leaves);
    meta.statistics["leaf_references"] = static_cast<double>(s.leaf_references);
    meta.statistics["max_depth"] = s.max_depth;
    meta.statistics["mean_leaf_triangles"] = s.mean_leaf_triangles;
    meta.statistics["sah_cost"] = s.sah_cost;
    meta.statistics["materials"] = static_cast<double>(scene->materials.size());
    meta.statistics["lights"] = static_cast<double>(scene->lights.size());
    if (!scene->textures.empty()) {
        meta.statistics["textures"] = static_cast<double>(scene->textures.size());
        meta.statistics["texels"] = static_cast<double>(scene->texels.size());
    }
    if (tree.repeated_triangles > 0) meta.statistics["repeated_triangles"] = static_cast<double>(tree.repeated_triangles);

    // The wide tree from the finished kd-tree and the triangles as the file stores them.
    WideTreeInput wide_in{tree.nodes.data(),
                          static_cast<std::uint32_t>(tree.nodes.size()),
                          tree.leaf_indices.data(),
                          static_cast<std::uint32_t>(tree.leaf_indices.size()),
                          scene->triangles.data(),
                          static_cast<std::uint32_t>(scene->triangles.size()),
                          {},
                          {}};
    for (int a = 0; a < 3; ++a) wide_in.bounds_min[a] = info.bounds_min[a], wide_in.bounds_max[a] = info.bounds_max[a];
    const std::vector<WideNode> wide = build_wide_tree(wide_in);
    if (!wide.empty()) {
        std::uint64_t used = 0;
        for (const WideNode& n : wide) used += wide_used_slots(n);
        meta.statistics["wide_nodes"] = static_cast<double>(wide.size());
        meta.statistics["wide_mean_children"] = static_cast<double>(used) / static_cast<double>(wide.size());
    }

    ContainerWriter w(FileKind::geometry);
    w.set_metadata(meta);
    w.add_record(section::geo_info, info);
    w.add(section::geo_nodes, ElementType::record, tree.nodes);
    w.add(section::geo_leaf_indices, ElementType::u32, tree.leaf_indices);
    w.add(section::geo_triangles, ElementType::record, scene->triangles);
    if (!scene->normals.empty()) w.add(section::geo_normals, ElementType::record, scene->normals);
    w.add(section::geo_materials, ElementType::record, scene->materials);
    w.add(section::geo_lights, ElementType::record, scene->lights);
    w.add_record(section::geo_camera, scene->camera);
    if (!wide.empty()) w.add(section::geo_wide, ElementType::record, wide);
    // Texture coordinates only matter to a textured material, so untextured scenes carry none.
    if (!scene->textures.empty()) {
        w.add(section::geo_uvs, ElementType::record, scene->uvs);
        w.add(section::geo_textures, ElementType::record, scene->textures);
        w.add(section::geo_texels, ElementType::record, scene->texels);
    }
    return w;
}

Scene scene_from_triangles(std::vector<TriangleRecord> triangles) {
    Scene s;
    s.triangles = std::move(triangles);
    MaterialRecord white{};
    for (float& d : white.diffuse) d = 0.8f;
    white.ior = 1.0f;
    s.materials.push_back(white);
    for (std::uint32_t i = 0; i < s.triangles.size(); ++i) {
        s.triangles[i].material = 0;
        s.triangles[i].source_index = i;
    }
    s.source_name = "triangles";
    frame_camera(s);
    return s;
}

}  // namespace kdpm
