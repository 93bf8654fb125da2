// kdpm-bench-rays: the binary kd walk and the wide walk (geometry.wide, format 1.2) on the same
// rays of the shipped Cornell box and the real scenes (../shared/scenes or $KDPM_SCENES): camera
// rays one at a time, diffuse bounce rays from their hits (incoherent, as photon paths and final
// gathering trace them) and shadow rays from the hits to the lights. Passes alternate, the ratio
// is the median of the pairs' ratios (the host's speed drifts within a run).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/scene_card.h"
#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/geometry/surface_normal.h"
#include "runtime/render/camera.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"
#include "runtime/shading/ray_offset.h"
#include "tools/bench/median_time.h"
#include "tools/cli/args.h"
#include "tools/cli/run_tool.h"
#include "tools/geometry/shared_scenes.h"

using namespace kdpm;
namespace fs = std::filesystem;

using cli::shared_scenes;

namespace {

struct RaySets {
    std::vector<Ray> primary, bounce, shadow;
};

RaySets make_rays(const GeometryFile& file, std::uint32_t size) {
    const GeometryView& g = file.view();
    RaySets s;
    const auto cam = PinholeCamera::from_record(file.camera(), size, size, 1);
    for (std::uint32_t y = 0; y < size; ++y)
        for (std::uint32_t x = 0; x < size; ++x) {
            const CameraRay r = cam.ray(x, y, 0);
            s.primary.push_back(Ray{r.origin, 0.0f, r.direction, INFINITY});
        }
    const float offset = render_ray_offset(g.info);
    for (std::size_t i = 0; i < s.primary.size(); ++i) {
        const Ray& p = s.primary[i];
        const Hit h = closest_hit_kd(g, p);
        if (!h.found()) continue;
        glm::vec3 n = geometric_normal(g.triangles[h.triangle]);
        if (glm::dot(n, p.direction) > 0.0f) n = -n;
        const glm::vec3 o = offset_origin(p.origin + h.t * p.direction, n, offset, true);
        s.bounce.push_back(Ray{o, 0.0f, cosine_direction(n, counter_random(7, i, 0, 0), counter_random(7, i, 0, 1)), INFINITY});
        if (g.light_count == 0) continue;
        const AreaLightRecord& l = g.lights[i % g.light_count];
        // Not point_on_light: this folds a triangle's sample (u + v > 1) where point_on_light warps
        // it by the square root; both are uniform, but the bench's rays must stay as they are.
        float u = counter_random(9, i, 0, 0), v = counter_random(9, i, 0, 1);
        if (l.shape == static_cast<std::uint32_t>(LightShape::triangle) && u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
        const glm::vec3 q = glm::vec3(l.p0[0], l.p0[1], l.p0[2]) + u * glm::vec3(l.e1[0], l.e1[1], l.e1[2]) +
                            v * glm::vec3(l.e2[0], l.e2[1], l.e2[2]);
        s.shadow.push_back(Ray{o, 0.0f, q - o, 0.999f});
    }
    return s;
}

struct Row {
    double binary_ms, wide_ms, ratio;
    std::size_t rays, differ;
};

Row compare(const GeometryView& g, const std::vector<Ray>& rays, bool any, int pairs) {
    GeometryView binary = g;
    binary.wide = nullptr;
    binary.wide_node_count = 0;
    std::vector<Hit> a(rays.size()), b(rays.size());
    std::vector<char> oa(rays.size()), ob(rays.size());
    std::vector<double> binary_ms, wide_ms;
    for (int p = 0; p < pairs + 1; ++p) {  // the first pair warms the caches
        binary_ms.push_back(bench::median_ms(1, [&] {
            cpu_parallel_for(rays.size(), [&](std::uint64_t i) {
                if (any) oa[i] = occluded(binary, rays[i]);
                else a[i] = closest_hit(binary, rays[i]);
            }, 256);
        }));
        wide_ms.push_back(bench::median_ms(1, [&] {
            cpu_parallel_for(rays.size(), [&](std::uint64_t i) {
                if (any) ob[i] = occluded(g, rays[i]);
                else b[i] = closest_hit(g, rays[i]);
            }, 256);
        }));
    }
    binary_ms.erase(binary_ms.begin());
    wide_ms.erase(wide_ms.begin());
    std::size_t differ = 0;
    for (std::size_t i = 0; i < rays.size(); ++i)
        differ += any ? oa[i] != ob[i] : a[i].found() != b[i].found() || a[i].t != b[i].t;
    return Row{bench::median_of(binary_ms), bench::median_of(wide_ms), bench::median_ratio(wide_ms, binary_ms),
               rays.size(), differ};
}

}  // namespace

int main(int argc, char** argv) {
    int pairs = 11, threads = 0, size = 512;
    cli::Args args("kdpm-bench-rays",
                   "Times the binary kd walk against the wide walk (format 1.2) on the same camera, bounce and shadow rays.");
    args.option("pairs", &pairs, "N", "alternated pairs of passes per row, the median ratio is printed (default 11)", 1, 1000)
        .option("size", &size, "N", "camera rays: N x N (default 512)", 16, 4096)
        .option("threads", &threads, "N", "worker threads, 0 = all cores (default 0)", 0, 4096);
    args.parse(argc, argv);
    return cli::run_tool("kdpm-bench-rays", [&] {
        ThreadLimit limit(threads);
        // The scenes' cards (camera, lights); the real scenes' meshes must be there.
        const fs::path cards = fs::path(KDPM_SOURCE_DIR) / "scenes";
        const struct {
            std::string name;
            fs::path card, mesh;
        } scenes[] = {{"cornell-box", cards / "cornell-box" / "cornell-box.json", {}},
                      {"sponza", cards / "sponza" / "sponza.json", shared_scenes() / "sponza" / "sponza.obj"},
                      {"conference", cards / "conference" / "conference.json",
                       shared_scenes() / "conference" / "conference.obj"}};
        std::printf("| scene | rays | count | binary ms | wide ms | wide / binary | hits that differ |\n");
        std::printf("|---|---|---:|---:|---:|---:|---:|\n");
        std::vector<std::string> sizes;
        for (const auto& scene : scenes) {
            const std::string& name = scene.name;
            std::error_code ec;
            if (!scene.mesh.empty() && !fs::is_regular_file(scene.mesh, ec)) {
                std::printf("| %s | skipped: %s not found (set KDPM_SCENES) | | | | | |\n", name.c_str(),
                            scene.mesh.string().c_str());
                continue;
            }
            const auto bytes = build_geometry_file(load_scene_input(scene.card), KdBuildParams{}).writer.bytes();
            const GeometryFile file = GeometryFile::from_bytes(bytes, name + ".kdg");
            const GeometryView& g = file.view();
            const RaySets rays = make_rays(file, static_cast<std::uint32_t>(size));
            const struct {
                const char* what;
                const std::vector<Ray>* rays;
                bool any;
            } sets[] = {{"camera, one at a time", &rays.primary, false},
                        {"diffuse bounce", &rays.bounce, false},
                        {"shadow (any hit)", &rays.shadow, true}};
            for (const auto& s : sets) {
                const Row r = compare(g, *s.rays, s.any, pairs);
                std::printf("| %s | %s | %zu | %.2f | %.2f | %.3fx | %zu |\n", name.c_str(), s.what, r.rays, r.binary_ms,
                            r.wide_ms, r.ratio, r.differ);
                std::fflush(stdout);
            }
            const double kd_bytes = 8.0 * g.node_count, wide_bytes = 256.0 * g.wide_node_count;
            char line[256];
            std::snprintf(line, sizeof line, "| %s | %u | %.2f | %.2f | %.1f | %.1f |", name.c_str(), g.triangle_count,
                          kd_bytes / 1e6, wide_bytes / 1e6, (bytes.size() - wide_bytes) / g.triangle_count,
                          static_cast<double>(bytes.size()) / g.triangle_count);
            sizes.push_back(line);
        }
        std::printf("\n| scene | triangles | kd nodes MB | wide nodes MB | .kdg bytes/triangle without wide | with wide |\n");
        std::printf("|---|---:|---:|---:|---:|---:|\n");
        for (const std::string& s : sizes) std::printf("%s\n", s.c_str());
        std::printf("\n'hits that differ': closest hits at another distance, or occlusion answered otherwise (ties at\n"
                    "the same distance may name the other triangle). Both walks are checked against brute force by\n"
                    "the tests.\n");
        return 0;
    });
}
