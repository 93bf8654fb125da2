// kdpm-build-photons PHOTONS.kdph -o MAP.kdp: builds the photon kd-trees (global map of every
// photon, caustic map of the caustic ones) with the VVH or the balanced median builder.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "builders/photons/photon_hits_file.h"
#include "builders/photons/photon_shards.h"
#include "formats/output_file.h"
#include "formats/scene_limits.h"
#include "builders/photons/photon_tree_builder.h"
#include "builders/photons/photon_map_writer.h"
#include "formats/container_reader.h"
#include "formats/container_writer.h"
#include "runtime/backend/thread_limit.h"
#include "tools/photons/irradiance_step.h"
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
        const std::filesystem::path inputs[] = {input};
        check_output_destination(output, inputs);
        ThreadLimit limit(threads);
        auto start = std::chrono::steady_clock::now();
        PhotonHitSet set = read_photon_hits(input);
        // A shard's photons carry the power of 1/N each but are only some of the N paths: its map
        // would be too dark.
        if (auto reader = ContainerReader::open(input, FileKind::photon_hits); reader.has_metadata()) {
            const PathRange paths = photon_hits_path_range(reader.metadata(), set.info);
            if (paths != PathRange{0, set.info.emitted_count})
                throw std::invalid_argument(input + " is a shard (paths " + path_range_text(paths) + " of " +
                                            std::to_string(set.info.emitted_count) +
                                            "): merge the shards with kdpm-merge-photons first");
        }
        if (radius_too_small(radius, set.info.bounds_min, set.info.bounds_max))
            throw std::invalid_argument("--radius " + radius_limit_text(radius, set.info.bounds_min, set.info.bounds_max) +
                                        ": no photon would be found (0 picks it)");

        PhotonTreeOptions options;
        options.builder = balanced ? PhotonTreeBuilder::balanced : PhotonTreeBuilder::vvh;
        options.leaf_size = static_cast<std::uint32_t>(leaf_size);
        options.query_radius = static_cast<float>(radius);
        cli::Progress progress("building photon trees", quiet);
        Metadata meta;
        meta.tool = "kdpm-build-photons";
        meta.tool_version = kdpm_version();
        meta.source_path = std::filesystem::path(input).filename().string();
        meta.source_hash = hash_file(input);
        IrradiancePrecompute irradiance;
        if (irradiance_every > 0) {
            meta.parameters["irradiance_every"] = std::to_string(irradiance_every);
            meta.parameters["irradiance_k"] = std::to_string(irradiance_k);
            irradiance = every_nth_photon_irradiance(static_cast<std::uint32_t>(irradiance_every),
                                                     static_cast<std::uint32_t>(irradiance_k));
        }
        PhotonMapBuild built = build_photon_map_file(set, options, meta, irradiance);
        progress.finish();
        const PhotonTreeInfo& global = built.global;
        const PhotonTreeInfo& caustic = built.caustic;
        built.writer.write(output);
        double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        if (!quiet) {
            auto bytes = std::filesystem::file_size(output);
            std::printf("kdpm-build-photons: %u photons (%u caustic, %u with irradiance), %s, %u nodes, %u leaves, "
                        "depth %u, largest leaf %u, r %.4g, %.2f s, %.1f MiB -> %s\n",
                        global.photon_count, caustic.photon_count, built.irradiance.photon_count,
                        balanced ? "balanced" : "VVH",
                        global.node_count, global.leaf_count, global.max_depth,
                        global.max_leaf_size, global.query_radius, secs, bytes / 1048576.0,
                        output.c_str());
        }
        return 0;
    });
}
