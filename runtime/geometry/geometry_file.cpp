#include "runtime/geometry/geometry_file.h"

#include <cstring>
#include <vector>

#include "formats/instance_layout.h"
#include "formats/section_ids.h"
#include "formats/tree_validation.h"
#include "runtime/geometry/instance_bvh.h"
#include "runtime/geometry/instance_lights.h"

namespace kdpm {

struct GeometryFile::Instances {
    std::vector<GeometryFile> files;
    std::vector<GeometryView> views;
    std::vector<InstancePlacement> placements;
    std::vector<InstanceNode> nodes;
    std::vector<AreaLightRecord> lights;
};

GeometryFile GeometryFile::open(const std::filesystem::path& path) {
    return GeometryFile(ContainerReader::open(path, FileKind::geometry), path.parent_path());
}

GeometryFile GeometryFile::from_bytes(std::span<const std::uint8_t> bytes, const std::string& name,
                                      const std::filesystem::path& folder) {
    return GeometryFile(ContainerReader::from_bytes(bytes, name, FileKind::geometry), folder);
}

GeometryFile::GeometryFile(GeometryFile&&) noexcept = default;
GeometryFile& GeometryFile::operator=(GeometryFile&&) noexcept = default;
GeometryFile::~GeometryFile() = default;

std::uint64_t GeometryFile::content_hash() const { return reader_.header().section_table_checksum; }

GeometryFile::GeometryFile(ContainerReader reader, const std::filesystem::path& folder) : reader_(std::move(reader)) {
    // Checksums, then the structural validator: linear in the file size, it checks every index
    // the kernels follow, so after it the traversal cannot leave the arrays or overflow its stack.
    validate_file(reader_, ValidationOptions{});
    if (reader_.find(section::geo_instances)) {
        open_instances(folder);
        return;
    }

    const auto nodes = reader_.section<KdNode>(section::geo_nodes);
    const auto leaf = reader_.section<std::uint32_t>(section::geo_leaf_indices);
    const auto tris = reader_.section<TriangleRecord>(section::geo_triangles);
    const auto mats = reader_.section<MaterialRecord>(section::geo_materials);
    const auto lights = reader_.section<AreaLightRecord>(section::geo_lights);
    const auto normals = reader_.optional_section<TriangleNormals>(section::geo_normals);

    view_.nodes = nodes.data();
    view_.node_count = static_cast<std::uint32_t>(nodes.size());
    view_.leaf_indices = leaf.data();
    view_.leaf_index_count = static_cast<std::uint32_t>(leaf.size());
    view_.triangles = tris.data();
    view_.triangle_count = static_cast<std::uint32_t>(tris.size());
    view_.normals = normals && !normals->empty() ? normals->data() : nullptr;
    view_.materials = mats.data();
    view_.material_count = static_cast<std::uint32_t>(mats.size());
    view_.lights = lights.data();
    view_.light_count = static_cast<std::uint32_t>(lights.size());
    const auto uvs = reader_.optional_section<TriangleUVs>(section::geo_uvs);
    const auto textures = reader_.optional_section<TextureRecord>(section::geo_textures);
    const auto texels = reader_.optional_section<Texel>(section::geo_texels);
    view_.uvs = uvs && !uvs->empty() ? uvs->data() : nullptr;
    if (textures && texels && !textures->empty()) {
        view_.textures = textures->data();
        view_.texture_count = static_cast<std::uint32_t>(textures->size());
        view_.texels = texels->data();
        view_.texel_count = texels->size();
    }
    // Format 1.2: the wide tree, when the file has it (older files walk the kd-tree alone).
    if (const auto wide = reader_.optional_section<WideNode>(section::geo_wide); wide && !wide->empty()) {
        view_.wide = wide->data();
        view_.wide_node_count = static_cast<std::uint32_t>(wide->size());
    }
    view_.info = reader_.record<GeometryInfo>(section::geo_info);
    camera_ = reader_.record<CameraRecord>(section::geo_camera);
}

// A scene of instances: every object file opened (and validated) once, however many instances
// place it; the placements with their inverses; the BVH over their world boxes; the lights of
// every placed object in world space after the scene's own (card) lights.
void GeometryFile::open_instances(const std::filesystem::path& folder) {
    auto parts = std::make_unique<Instances>();
    const auto objects = reader_.section<ObjectReference>(section::geo_objects);
    const auto records = reader_.section<InstanceRecord>(section::geo_instances);
    parts->files.reserve(objects.size());
    for (const ObjectReference& o : objects) {
        const std::filesystem::path path = folder / std::filesystem::path(std::string(o.path));
        GeometryFile object = [&] {
            try {
                return GeometryFile::open(path);
            } catch (const std::exception& e) {
                throw FormatError(reader_.name() + ": object " + std::string(o.path) + ": " + e.what());
            }
        }();
        if (object.has_instances())
            throw FormatError(reader_.name() + ": object " + path.string() +
                              " places instances itself; a scene places objects one level deep");
        if (object.content_hash() != o.content_hash)
            throw FormatError(reader_.name() + ": object " + path.string() +
                              " has changed since the scene was built (content hash differs): rebuild the scene "
                              "with kdpm-build-geometry");
        parts->files.push_back(std::move(object));
    }
    for (const GeometryFile& f : parts->files) parts->views.push_back(f.view());

    std::vector<WorldBox> boxes;
    boxes.reserve(records.size());
    parts->placements.reserve(records.size());
    for (const InstanceRecord& r : records) {
        InstancePlacement p{};
        std::memcpy(p.world_from_object.m, r.world_from_object, sizeof p.world_from_object.m);
        p.object_from_world = inverse_affine(p.world_from_object);
        p.object = r.object;
        parts->placements.push_back(p);
        boxes.push_back(placed_bounds(parts->views[r.object].info, p.world_from_object));
    }
    parts->nodes = build_instance_bvh(boxes);
    const auto own_lights = reader_.section<AreaLightRecord>(section::geo_lights);
    parts->lights.assign(own_lights.begin(), own_lights.end());
    append_placed_lights(parts->views, parts->placements, parts->lights);

    camera_ = reader_.record<CameraRecord>(section::geo_camera);
    const GeometryInfo scene_info = reader_.record<GeometryInfo>(section::geo_info);
    if (records.size() == 1 && is_identity_affine(parts->placements[0].world_from_object)) {
        // One object placed as it is: its own tree, so that wrapping an asset in a scene costs no
        // ray anything. Its hits name no instance; the scene's lights and defaults stay.
        view_ = parts->views[records[0].object];
        view_.lights = parts->lights.data();
        view_.light_count = static_cast<std::uint32_t>(parts->lights.size());
        view_.info.default_photons = scene_info.default_photons;
        view_.info.default_bounces = scene_info.default_bounces;
        view_.info.default_k = scene_info.default_k;
        view_.info.up_axis = scene_info.up_axis;
        instances_ = std::move(parts);
        return;
    }
    view_ = GeometryView{};
    view_.info = scene_info;
    const InstanceNode& root = parts->nodes[0];
    for (int a = 0; a < 3; ++a) view_.info.bounds_min[a] = root.lo[a], view_.info.bounds_max[a] = root.hi[a];
    view_.lights = parts->lights.data();
    view_.light_count = static_cast<std::uint32_t>(parts->lights.size());
    view_.objects = parts->views.data();
    view_.object_count = static_cast<std::uint32_t>(parts->views.size());
    view_.instances = parts->placements.data();
    view_.instance_count = static_cast<std::uint32_t>(parts->placements.size());
    view_.instance_nodes = parts->nodes.data();
    view_.instance_node_count = static_cast<std::uint32_t>(parts->nodes.size());
    instances_ = std::move(parts);
}

}  // namespace kdpm
