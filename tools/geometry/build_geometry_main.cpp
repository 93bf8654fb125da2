// kdpm-build-geometry INPUT -o scene.kdg: scene card or mesh -> SAH geometry kd-tree file.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "runtime/backend/thread_limit.h"
#include "tools/cli/args.h"
#include "tools/cli/progress.h"
#include "tools/cli/run_tool.h"
#include "tools/cli/sah_cost_options.h"
#include "tools/jobs/geometry_job.h"

using namespace kdpm;

int main(int argc, char** argv) {
    std::string input, output;
    bool quiet = false;
    int threads = 0;
    cli::SahCosts costs;
    KdBuildParams params;
    int exact_below = static_cast<int>(params.exact_below);
    int clip_below = static_cast<int>(params.clip_below);
    cli::Args args("kdpm-build-geometry",
                   "Builds the SAH geometry kd-tree (.kdg) of a scene card (.json) or a mesh (OBJ, glTF, PLY, ...).");
    args.positional("INPUT", &input, "scene card (.json) or mesh file")
        .option("output", &output, "FILE", "output .kdg file");
    cli::add_sah_cost_options(args, costs);
    args.option("max-depth", &params.max_depth, "N", "depth limit, 0 = automatic: 8 + 1.3 log2(triangles), nodes of at most 16 triangles 4 + log2(triangles) (fast: at most 32, 2 + log2(triangles)) (default 0)", 0, 60)
        .option("leaf-size", &params.leaf_size, "N", "nodes with at most N triangles stay leaves (default 0)", 0, 1 << 20)
        .option("quality", "fast|high",
                "fast: binned SAH in large nodes, exact below --exact-below triangles, crossing triangles bounded by "
                "boxes below --clip-below; high: exact SAH sweep "
                "with perfect splits everywhere (default high)",
                [&](const std::string& v) {
                    const auto q = parse_quality(v);
                    if (!q) throw std::invalid_argument("expected fast or high, got '" + v + "'");
                    params.quality = *q;
                })
        .option("exact-below", &exact_below, "N", "fast: nodes with fewer triangles use the exact sweep (default 4096)",
                1, 1 << 30)
        .option("clip-below", &clip_below, "N",
                "fast: exact-sweep nodes with fewer triangles cut a crossing triangle's bounds at the split instead "
                "of clipping the triangle, 0 = clip everywhere (default 12)",
                0, 1 << 30)
        .option("threads", &threads, "N", "worker threads, 0 = all cores (default 0)", 0, 4096)
        .flag("quiet", &quiet, "print nothing but errors");
    args.short_name('o', "output");
    args.parse(argc, argv);
    params = cli::with_costs(params, costs);
    params.exact_below = static_cast<std::uint32_t>(exact_below);
    params.clip_below = static_cast<std::uint32_t>(clip_below);

    return cli::run_tool("kdpm-build-geometry", [&] {
        if (output.empty()) throw std::runtime_error("no output file given (-o FILE)");
        ThreadLimit limit(threads);
        const GeometryJobResult built = [&] {
            cli::Progress progress("building kd-tree", quiet);
            auto b = build_geometry_job(input, output, params, [&](double f) { progress.update(f); });
            progress.finish();
            return b;
        }();
        if (!quiet)
            for (const std::string& w : built.warnings) std::fprintf(stderr, "kdpm-build-geometry: warning: %s\n", w.c_str());
        if (!quiet && built.instances > 0) {
            std::printf("%s: %zu instance%s of %zu object%s, %zu triangles placed, %.0f ms\n", output.c_str(),
                        built.instances, built.instances == 1 ? "" : "s", built.objects, built.objects == 1 ? "" : "s",
                        built.triangles, built.build_ms);
        } else if (!quiet) {
            const KdTreeStats& s = built.stats;
            std::error_code ec;
            const auto bytes = std::filesystem::file_size(output, ec);
            std::printf("%s: %zu triangles, %llu nodes, %llu leaves (%llu empty), depth %u, %.2f triangles/leaf, "
                        "SAH cost %.2f, import %.0f ms, build %.0f ms, %.1f MB\n",
                        output.c_str(), built.triangles, static_cast<unsigned long long>(s.nodes),
                        static_cast<unsigned long long>(s.leaves), static_cast<unsigned long long>(s.empty_leaves),
                        s.max_depth, s.mean_leaf_triangles, s.sah_cost, built.import_ms, built.build_ms,
                        static_cast<double>(bytes) / 1e6);
        }
        return 0;
    });
}
