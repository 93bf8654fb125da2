#include "tools/bench/instance_bench.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <vector>

#include "builders/geometry/instanced_scene_builder.h"
#include "builders/geometry/scene_card.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/geometry/instance_view.h"
#include "runtime/render/camera.h"
#include "tools/bench/camera_packets.h"
#include "tools/bench/text_table.h"

namespace kdpm::bench {
namespace fs = std::filesystem;
namespace {

std::string json_vec(const float* v) { return fmt("[%.9g, %.9g, %.9g]", v[0], v[1], v[2]); }

std::string camera_json(const CameraRecord& c, const float* shift) {
    float eye[3], at[3];
    for (int a = 0; a < 3; ++a) eye[a] = c.eye[a] + shift[a], at[a] = c.lookat[a] + shift[a];
    return fmt("\"camera\": {\"eye\": %s, \"lookat\": %s, \"up\": %s, \"vfov\": %.9g, \"width\": %u, \"height\": %u}",
               json_vec(eye).c_str(), json_vec(at).c_str(), json_vec(c.up).c_str(), c.vfov_degrees, c.width, c.height);
}

// A card placing `object` (a file name in the card's folder), built as kdpm-build-geometry builds
// it; the scene file's path.
fs::path build_card(const fs::path& dir, const std::string& name, const std::string& body) {
    const fs::path card = dir / (name + ".json"), out = dir / (name + ".kdg");
    std::ofstream(card) << "{ " << body << " }\n";
    const InstancedSceneBuild b = build_instanced_scene(read_instance_card(card), card, out);
    b.writer.write(out);
    return out;
}

// Camera packets of `scene` and of `object`, the same camera (shifted into the scene's frame),
// passes in pairs so that both see the same machine.
PairedTimes paired_packets(const GeometryFile& scene, const CameraRecord& scene_camera, const GeometryFile& object,
                           std::uint32_t width, std::uint32_t height, int pairs, double* same_hits = nullptr) {
    const PinholeCamera a = PinholeCamera::from_record(scene_camera, width, height, 1);
    const PinholeCamera b = PinholeCamera::from_record(object.camera(), width, height, 1);
    std::vector<Hit> ha, hb;
    std::vector<double> ta, tb;
    for (int p = 0; p <= pairs; ++p) {
        const double x = trace_camera_packets(scene.view(), a, ha), y = trace_camera_packets(object.view(), b, hb);
        if (p == 0) continue;  // warm-up
        ta.push_back(x);
        tb.push_back(y);
    }
    if (same_hits) {
        std::size_t same = 0;
        for (std::size_t i = 0; i < ha.size(); ++i) same += ha[i].found() == hb[i].found() && ha[i].triangle == hb[i].triangle;
        *same_hits = ha.empty() ? 1.0 : double(same) / ha.size();
    }
    return paired_times(ta, tb);
}

}  // namespace

InstanceFigures run_instance_bench(const InstanceBenchConfig& c) {
    InstanceFigures f;
    const GeometryFile object = GeometryFile::open(c.object);
    const GeometryInfo& info = object.view().info;
    const CameraRecord camera = object.camera();
    const std::string name = c.object.filename().string();
    if (!fs::equivalent(c.object.parent_path(), c.work_dir))
        fs::copy_file(c.object, c.work_dir / name, fs::copy_options::overwrite_existing);
    const float none[3] = {0, 0, 0};

    const fs::path as_is = build_card(c.work_dir, c.name + "-one", "\"instances\": [{\"object\": \"" + name + "\"}], " +
                                                                       camera_json(camera, none));
    // Moved by a tenth of the scene's size on every axis: no longer the identity, so the instance
    // walk runs; the camera moves alike and sees the same picture.
    float shift[3];
    for (int a = 0; a < 3; ++a) shift[a] = 0.1f * (info.bounds_max[a] - info.bounds_min[a]) + 1.0f;
    const fs::path moved = build_card(c.work_dir, c.name + "-moved",
                                      "\"instances\": [{\"object\": \"" + name + "\", \"translate\": " + json_vec(shift) +
                                          "}], " + camera_json(camera, shift));
    // The grid: copies a twentieth of the scene's size apart in x and z; the inside camera in
    // the middle copy.
    float step[3] = {1.05f * (info.bounds_max[0] - info.bounds_min[0]), 0.0f, 1.05f * (info.bounds_max[2] - info.bounds_min[2])};
    float middle[3] = {step[0] * float(c.grid_x / 2), 0.0f, step[2] * float(c.grid_z / 2)};
    const std::string grid = fmt("\"instances\": [{\"object\": \"%s\", \"repeat\": {\"count\": [%u, 1, %u], \"step\": %s}}]",
                                 name.c_str(), c.grid_x, c.grid_z, json_vec(step).c_str());
    fs::path inside;
    f.scene_build_ms = median_ms(3, [&] { inside = build_card(c.work_dir, c.name + "-grid", grid + ", " + camera_json(camera, middle)); });
    const fs::path overview = build_card(c.work_dir, c.name + "-grid-overview", grid);
    f.object_build_ms = c.object_build_ms;
    f.object_bytes = fs::file_size(c.object);
    f.scene_bytes = fs::file_size(inside);

    f.load_ms = median_ms(c.pairs, [&] { (void)GeometryFile::open(inside); });
    const GeometryFile one = GeometryFile::open(as_is), shifted = GeometryFile::open(moved);
    const GeometryFile many = GeometryFile::open(inside), whole = GeometryFile::open(overview);
    f.instances = many.view().instance_count;
    f.placed_triangles = std::uint64_t(f.instances) * info.triangle_count;
    f.runtime_bytes_per_instance =
        (double(many.view().instance_count) * sizeof(InstancePlacement) +
         double(many.view().instance_node_count) * sizeof(InstanceNode) +
         double(many.view().light_count - object.view().light_count) * sizeof(AreaLightRecord)) / double(f.instances);
    f.one_as_is = paired_packets(one, one.camera(), object, c.width, c.height, c.pairs);
    f.one_moved = paired_packets(shifted, shifted.camera(), object, c.width, c.height, c.pairs, &f.moved_same_hits);
    f.grid_inside = paired_packets(many, many.camera(), object, c.width, c.height, c.pairs);
    f.grid_overview = paired_packets(whole, whole.camera(), object, c.width, c.height, c.pairs);
    f.measured = true;
    return f;
}

}  // namespace kdpm::bench
