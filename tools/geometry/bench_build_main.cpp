// kdpm-bench-build: times the SAH kd-tree build, both qualities, on the shipped Cornell box and the
// real scenes (../shared/scenes or $KDPM_SCENES), median of several runs. Import time is not
// included.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "builders/geometry/sah/sah_kd_builder.h"
#include "builders/geometry/scene_card.h"
#include "runtime/backend/thread_limit.h"
#include "tools/cli/args.h"
#include "tools/cli/run_tool.h"
#include "tools/cli/sah_cost_options.h"
#include "tools/geometry/shared_scenes.h"

using namespace kdpm;
namespace fs = std::filesystem;

using cli::shared_scenes;

int main(int argc, char** argv) {
    int runs = 5, threads = 0;
    std::string extra;
    cli::Args args("kdpm-bench-build", "Times the SAH geometry kd-tree build on the shipped and the shared scenes.");
    args.option("runs", &runs, "N", "builds per scene, the median is printed (default 5)", 1, 1000)
        .option("threads", &threads, "N", "worker threads, 0 = all cores (default 0)", 0, 4096)
        .positional("INPUT", &extra, "an extra scene card or mesh to time", false);
    cli::SahCosts costs;
    cli::add_sah_cost_options(args, costs);
    args.parse(argc, argv);
    return cli::run_tool("kdpm-bench-build", [&] {
        ThreadLimit limit(threads);
        std::vector<std::pair<std::string, fs::path>> scenes = {
            {"cornell-box", fs::path(KDPM_SOURCE_DIR) / "scenes" / "cornell-box" / "cornell-box.json"},
            {"sponza", shared_scenes() / "sponza" / "sponza.obj"},
            {"conference", shared_scenes() / "conference" / "conference.obj"}};
        if (!extra.empty()) scenes.push_back({fs::path(extra).stem().string(), extra});
        const KdBuildParams chosen = cli::with_costs(KdBuildParams{}, costs);
        std::printf("SAH costs: traversal %g, intersection %g, empty bonus %g\n", chosen.traversal_cost,
                    chosen.intersection_cost, chosen.empty_bonus);
        std::printf("%-12s %-7s %10s %10s %8s %10s %6s %9s\n", "scene", "quality", "triangles", "build ms", "Mtris/s",
                    "nodes", "depth", "SAH cost");
        for (const auto& [name, path] : scenes) {
            std::error_code ec;
            if (!fs::is_regular_file(path, ec)) {
                std::printf("%-12s skipped: %s not found (set KDPM_SCENES)\n", name.c_str(), path.string().c_str());
                continue;
            }
            const Scene scene = load_scene_input(path);
            for (const KdBuildQuality quality : {KdBuildQuality::high, KdBuildQuality::fast}) {
                KdBuildParams params = chosen;
                params.quality = quality;
                std::vector<double> ms;
                KdTree tree;
                for (int r = 0; r < runs; ++r) {
                    const auto t0 = std::chrono::steady_clock::now();
                    tree = build_sah_kd_tree(scene.triangles, params);
                    ms.push_back(
                        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
                }
                std::sort(ms.begin(), ms.end());
                const double median = ms[ms.size() / 2];
                std::printf("%-12s %-7s %10zu %10.1f %8.2f %10llu %6u %9.2f\n", name.c_str(),
                            std::string(quality_name(quality)).c_str(), scene.triangles.size(), median,
                            static_cast<double>(scene.triangles.size()) / (median * 1e3),
                            static_cast<unsigned long long>(tree.stats.nodes), tree.stats.max_depth,
                            tree.stats.sah_cost);
            }
            std::fflush(stdout);
        }
        return 0;
    });
}
