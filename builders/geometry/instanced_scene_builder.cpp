#include "builders/geometry/instanced_scene_builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "formats/container_reader.h"
#include "formats/format_error.h"
#include "formats/metadata.h"
#include "formats/section_ids.h"
#include "formats/tree_validation.h"

namespace kdpm {

namespace fs = std::filesystem;

namespace {

struct ObjectFacts {
    ObjectReference reference{};
    GeometryInfo info{};
};

ObjectFacts object_facts(const fs::path& object, const fs::path& output) {
    ObjectFacts f;
    const ContainerReader r = [&] {
        try {
            ContainerReader reader = ContainerReader::open(object, FileKind::geometry);
            validate_file(reader, ValidationOptions{});
            return reader;
        } catch (const std::exception& e) {
            throw FormatError("object " + object.string() + ": " + e.what());
        }
    }();
    if (r.find(section::geo_instances))
        throw FormatError("object " + object.string() + " places instances itself; a scene places objects one level deep");
    f.info = r.record<GeometryInfo>(section::geo_info);
    // Stored relative to the scene file, so the two move together.
    std::error_code ec;
    const fs::path base = fs::weakly_canonical(fs::absolute(output).parent_path(), ec);
    const fs::path target = fs::weakly_canonical(fs::absolute(object), ec);
    const std::string rel = target.lexically_relative(base).generic_string();
    if (rel.empty() || rel.size() >= kObjectPathBytes)
        throw FormatError("object " + object.string() + ": its path from the output's folder is longer than " +
                          std::to_string(kObjectPathBytes - 1) + " bytes");
    std::memcpy(f.reference.path, rel.data(), rel.size());
    f.reference.content_hash = r.header().section_table_checksum;
    f.reference.triangle_count = f.info.triangle_count;
    return f;
}

}  // namespace

InstancedSceneBuild build_instanced_scene(const InstanceCard& card, const fs::path& card_path, const fs::path& output) {
    std::vector<ObjectFacts> objects;
    for (const fs::path& o : card.objects) objects.push_back(object_facts(o, output));

    InstancedSceneBuild out;
    double lo[3], hi[3];
    for (int a = 0; a < 3; ++a) lo[a] = std::numeric_limits<double>::infinity(), hi[a] = -lo[a];
    for (const InstanceRecord& r : card.instances) {
        const GeometryInfo& b = objects[r.object].info;
        out.placed_triangles += b.triangle_count;
        for (int corner = 0; corner < 8; ++corner) {
            const double p[3] = {(corner & 1) ? b.bounds_max[0] : b.bounds_min[0],
                                 (corner & 2) ? b.bounds_max[1] : b.bounds_min[1],
                                 (corner & 4) ? b.bounds_max[2] : b.bounds_min[2]};
            for (int i = 0; i < 3; ++i) {
                const float* row = r.world_from_object + 4 * i;
                const double q = row[0] * p[0] + row[1] * p[1] + row[2] * p[2] + row[3];
                lo[i] = std::min(lo[i], q), hi[i] = std::max(hi[i], q);
            }
        }
    }
    GeometryInfo info{};
    float flo[3], fhi[3];
    for (int a = 0; a < 3; ++a) {
        if (!(std::fabs(lo[a]) < 1e18 && std::fabs(hi[a]) < 1e18))
            throw FormatError(card_path.string() + ": the placed objects reach beyond coordinate 1e18");
        flo[a] = info.bounds_min[a] = static_cast<float>(lo[a]);
        fhi[a] = info.bounds_max[a] = static_cast<float>(hi[a]);
    }
    Scene settings = card.settings;
    if (!card.card_camera) frame_camera_on(settings, flo, fhi);
    info.default_photons = settings.photons;
    info.default_bounces = settings.bounces;
    info.default_k = settings.k;
    info.up_axis = settings.up_axis;

    Metadata meta;
    meta.tool = "kdpm-build-geometry";
    meta.tool_version = kdpm_version();
    meta.source_path = card_path.filename().string();
    meta.source_hash = hash_file(card_path.string());
    meta.statistics["objects"] = static_cast<double>(objects.size());
    meta.statistics["instances"] = static_cast<double>(card.instances.size());
    meta.statistics["placed_triangles"] = static_cast<double>(out.placed_triangles);
    meta.statistics["lights"] = static_cast<double>(settings.lights.size());

    std::vector<ObjectReference> refs;
    for (const ObjectFacts& f : objects) refs.push_back(f.reference);
    ContainerWriter& w = out.writer;
    w.set_metadata(meta);
    w.add_record(section::geo_info, info);
    w.add_record(section::geo_camera, settings.camera);
    w.add(section::geo_lights, ElementType::record, settings.lights);
    w.add(section::geo_objects, ElementType::record, refs);
    w.add(section::geo_instances, ElementType::record, card.instances);
    return out;
}

}  // namespace kdpm
