// kdpm-build-photons PHOTONS.kdph -o MAP.kdp: builds the photon kd-trees (global map of every
// photon, caustic map of the caustic ones) with the VVH or the balanced median builder.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "builders/photons/photon_tree_builder.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/photons/knn_best.h"
#include "tools/jobs/photon_jobs.h"
#include "tools/cli/args.h"
#include "tools/cli/progress.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;

int main(int argc, char** argv) {
    std::string input, output;
    bool balanced = false, quiet = false;
    int leaf_size = 0, threads = 0;  // 0: the builder's default
    int irradiance_every = static_cast<int>(kDefaultIrradianceEvery);
    int irradiance_k = static_cast<int>(kDefaultIrradianceK);
    double radius = 0.0;
    // The help's defaults are the library's (the leaf size's 0 picks the builder's own).
    const std::string default_leaf = std::to_string(kVvhLeafSize) + "; " + std::to_string(kBalancedLeafSize) +
                                     " with --balanced",
                      default_every = std::to_string(irradiance_every),
                      default_k = std::to_string(irradiance_k);
    cli::Args args("kdpm-build-photons", "Builds the photon kd-tree file (.kdp) from photon hits (.kdph).");
    args.positional("PHOTONS.kdph", &input, "photon hits from kdpm-shoot-photons")
        .option("output", &output, "FILE.kdp", "output file")
        .flag("balanced", &balanced, "classic balanced median-split tree instead of VVH")
        .option("leaf-size", &leaf_size, "N", "most photons per leaf (default " + default_leaf + ")", 1, 4096)
        .option("radius", &radius, "R", "VVH expected query radius (default: estimated for k = 32)", 0.0, 1e30)
        .option("irradiance-every", &irradiance_every, "N",
                "precompute the irradiance at every N-th photon for final gathering (default " + default_every +
                    "; 0: none)",
                0, 1 << 30)
        .option("irradiance-k", &irradiance_k, "K",
                "photons per precomputed irradiance estimate (default " + default_k + ")", 1,
                static_cast<int>(kMaxGatherK))
        .option("threads", &threads, "N", "worker threads (default: all cores)", 0, 1024)
        .flag("quiet", &quiet, "print nothing on success");
    args.short_name('o', "output");
    args.parse(argc, argv);
    return cli::run_tool("kdpm-build-photons", [&] {
        if (output.empty()) throw std::invalid_argument("no output file (use -o FILE.kdp)");
        ThreadLimit limit(threads);
        PhotonMapJob job;
        job.balanced = balanced;
        job.leaf_size = static_cast<std::uint32_t>(leaf_size);
        job.radius = radius;
        job.irradiance_every = static_cast<std::uint32_t>(irradiance_every);
        job.irradiance_k = static_cast<std::uint32_t>(irradiance_k);
        cli::Progress progress("building photon trees", quiet);
        const PhotonMapJobResult built = build_photon_map_job(input, output, job);
        progress.finish();

        if (!quiet) {
            const PhotonTreeInfo& global = built.global;
            auto bytes = std::filesystem::file_size(output);
            std::printf("kdpm-build-photons: %u photons (%u caustic, %u with irradiance), %s, %u nodes, %u leaves, "
                        "depth %u, largest leaf %u, r %.4g, %.2f s, %.1f MiB -> %s\n",
                        global.photon_count, built.caustic.photon_count, built.irradiance_photons,
                        balanced ? "balanced" : "VVH", global.node_count, global.leaf_count, global.max_depth,
                        global.max_leaf_size, global.query_radius, built.seconds, bytes / 1048576.0, output.c_str());
        }
        return 0;
    });
}
