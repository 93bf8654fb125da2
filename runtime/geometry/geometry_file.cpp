#include "runtime/geometry/geometry_file.h"

#include "formats/section_ids.h"
#include "formats/tree_validation.h"

namespace kdpm {

GeometryFile GeometryFile::open(const std::filesystem::path& path) {
    return GeometryFile(ContainerReader::open(path, FileKind::geometry));
}

GeometryFile GeometryFile::from_bytes(std::span<const std::uint8_t> bytes, const std::string& name) {
    return GeometryFile(ContainerReader::from_bytes(bytes, name, FileKind::geometry));
}

GeometryFile::GeometryFile(ContainerReader reader) : reader_(std::move(reader)) {
    // Checksums, then the structural validator: linear in the file size, it checks every index
    // the kernels follow, so after it the traversal cannot leave the arrays or overflow its stack.
    validate_file(reader_, ValidationOptions{});

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

}  // namespace kdpm
