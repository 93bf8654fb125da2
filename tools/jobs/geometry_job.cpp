#include "tools/jobs/geometry_job.h"

#include <chrono>
#include <span>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/instanced_scene_builder.h"
#include "builders/geometry/scene_card.h"
#include "formats/output_file.h"

namespace kdpm {

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

GeometryJobResult build_and_write(const Scene& scene, const std::filesystem::path& output, const KdBuildParams& params,
                                  const std::function<void(double)>& progress) {
    GeometryJobResult result;
    result.triangles = scene.triangles.size();
    result.warnings = scene.warnings;
    const auto start = std::chrono::steady_clock::now();
    GeometryBuild build = build_geometry_file(scene, params, progress);
    result.build_ms = ms_since(start);
    build.writer.write(output);
    result.stats = build.stats;
    if (build.repeated_triangles > 0)
        result.warnings.push_back(std::to_string(build.repeated_triangles) +
                                  " triangles are exact copies of earlier ones; the tree holds the first copy only");
    if (build.stats.max_leaf_triangles > kLargeLeafTriangles)
        result.warnings.push_back("a leaf holds " + std::to_string(build.stats.max_leaf_triangles) +
                                  " triangles (overlapping triangles that no split separates); rays through it will "
                                  "be slow");
    return result;
}

}  // namespace

GeometryJobResult build_geometry_job(const std::filesystem::path& input, const std::filesystem::path& output,
                                     const KdBuildParams& params, const std::function<void(double)>& progress) {
    std::vector<std::filesystem::path> inputs{input};
    if (card_places_instances(input)) {
        const InstanceCard card = read_instance_card(input);
        inputs.insert(inputs.end(), card.objects.begin(), card.objects.end());
        check_output_destination(output, inputs);
        const auto start = std::chrono::steady_clock::now();
        InstancedSceneBuild build = build_instanced_scene(card, input, output);
        build.writer.write(output);
        GeometryJobResult result;
        result.triangles = build.placed_triangles;
        result.instances = card.instances.size();
        result.objects = card.objects.size();
        result.build_ms = ms_since(start);
        if (progress) progress(1.0);
        return result;
    }
    if (is_scene_card(input)) inputs.push_back(card_mesh_path(input));
    check_output_destination(output, inputs);
    const auto start = std::chrono::steady_clock::now();
    const Scene scene = load_scene_input(input);
    const double import_ms = ms_since(start);
    GeometryJobResult result = build_and_write(scene, output, params, progress);
    result.import_ms = import_ms;
    return result;
}

GeometryJobResult build_geometry_job(const Scene& scene, const std::filesystem::path& output,
                                     const KdBuildParams& params, const std::function<void(double)>& progress) {
    check_output_destination(output, std::span<const std::filesystem::path>{});
    return build_and_write(scene, output, params, progress);
}

}  // namespace kdpm
