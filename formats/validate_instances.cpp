// Structural checks of a .kdg of instances (format 1.3): a scene that places other .kdg files.
// It holds no triangles of its own; its objects are named by path and content hash and are
// checked, with their hashes, when the runtime opens them (runtime/geometry/geometry_file.cpp).
#include <cstdint>
#include <cstring>
#include <string>

#include "formats/affine_map.h"
#include "formats/camera_check.h"
#include "formats/instance_layout.h"
#include "formats/section_ids.h"
#include "formats/validate_kinds.h"

namespace kdpm {
namespace {

[[noreturn]] void fail(const ContainerReader& file, const std::string& why) {
    throw FormatError(file.name() + ": invalid scene of instances: " + why);
}

void check_sections(const ContainerReader& file) {
    const std::uint32_t own_triangles[] = {section::geo_nodes,    section::geo_leaf_indices, section::geo_triangles,
                                           section::geo_normals,  section::geo_uvs,          section::geo_textures,
                                           section::geo_texels,   section::geo_wide};
    for (std::uint32_t id : own_triangles)
        if (file.find(id))
            fail(file, "it holds section " + ContainerReader::section_label(id) +
                           "; a scene of instances has no triangles of its own (place them as an object)");
    const std::uint32_t records[] = {section::geo_info,   section::geo_camera,  section::geo_lights,
                                     section::geo_objects, section::geo_instances, section::geo_materials};
    for (std::uint32_t id : records)
        if (const SectionEntry* e = file.find(id); e && e->element_type != static_cast<std::uint32_t>(ElementType::record))
            fail(file, "section " + ContainerReader::section_label(id) + " must hold records");
}

void check_objects(const ContainerReader& file, std::span<const ObjectReference> objects) {
    if (objects.empty()) fail(file, "it places no objects");
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const ObjectReference& o = objects[i];
        const std::size_t length = strnlen(o.path, kObjectPathBytes);
        if (length == 0 || length == kObjectPathBytes)
            fail(file, "object " + std::to_string(i) + " has an empty or unterminated path");
        for (std::size_t c = length; c < kObjectPathBytes; ++c)
            if (o.path[c] != 0) fail(file, "object " + std::to_string(i) + " has bytes after its path");
        if (o.reserved != 0) fail(file, "object " + std::to_string(i) + " has a non-zero reserved field");
    }
}

void check_instances(const ContainerReader& file, std::span<const InstanceRecord> instances, std::size_t objects) {
    if (instances.empty()) fail(file, "it has no instances");
    if (instances.size() > kMaxInstances)
        fail(file, std::to_string(instances.size()) + " instances exceed " + std::to_string(kMaxInstances));
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const InstanceRecord& r = instances[i];
        if (r.object >= objects) fail(file, "instance " + std::to_string(i) + " names an object out of range");
        Affine m;
        std::memcpy(m.m, r.world_from_object, sizeof m.m);
        if (!usable_affine(m))
            fail(file, "instance " + std::to_string(i) + " has a transform that is not finite or not invertible");
        if (r.reserved[0] != 0 || r.reserved[1] != 0 || r.reserved[2] != 0)
            fail(file, "instance " + std::to_string(i) + " has a non-zero reserved field");
    }
}

}  // namespace

void validate_instanced_scene_file(const ContainerReader& file, const ValidationOptions&) {
    check_sections(file);
    const GeometryInfo& info = file.record<GeometryInfo>(section::geo_info);
    if (info.triangle_count != 0 || info.node_count != 0 || info.leaf_index_count != 0 || info.max_depth != 0)
        fail(file, "geometry.info counts triangles or nodes of its own");
    check_scene_defaults(file, info);
    try {
        check_camera(file.record<CameraRecord>(section::geo_camera), file.name() + ": invalid scene of instances");
    } catch (const std::runtime_error& e) {
        throw FormatError(e.what());
    }
    check_lights(file, file.section<AreaLightRecord>(section::geo_lights), 0);
    const auto objects = file.section<ObjectReference>(section::geo_objects);
    check_objects(file, objects);
    check_instances(file, file.section<InstanceRecord>(section::geo_instances), objects.size());
}

}  // namespace kdpm
