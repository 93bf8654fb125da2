// kdpm-shoot-photons SCENE.kdg -n COUNT --bounces B -o PHOTONS.kdph: traces photon paths from the
// scene's area lights and stores every diffuse hit (with its bounce index and caustic flag).
// --paths BEGIN:END traces only those paths of the COUNT, a shard for kdpm-merge-photons.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "builders/photons/photon_hits_file.h"
#include "builders/photons/photon_shards.h"
#include "formats/output_file.h"
#include "runtime/backend/backend_kind.h"
#include "runtime/backend/cuda_device.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_shooter.h"
#include "tools/cli/args.h"
#include "tools/cli/progress.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;

int main(int argc, char** argv) {
    std::string input, output, paths;
    bool quiet = false;
    int photons = 0, bounces = -1, threads = 0, seed = 0;
    BackendRequest backend = BackendRequest::cpu;
    cli::Args args("kdpm-shoot-photons", "Shoots photons from the area lights of a .kdg scene into a photon hit file (.kdph).");
    args.positional("SCENE.kdg", &input, "geometry file from kdpm-build-geometry")
        .option("output", &output, "FILE.kdph", "output file")
        .option("photons", &photons, "N", "photon paths to emit (default: the scene card's)", 1, 1 << 30)
        .option("bounces", &bounces, "B", "most bounces per path (default: the scene card's, else 4)", 0, 255)
        .option("paths", "BEGIN:END", "shoot only paths BEGIN..END-1 of the N (a shard; default all)",
                [&](const std::string& v) {
                    parse_path_range(v, UINT64_MAX);  // the syntax here; END <= N once N is known
                    paths = v;
                })
        .option("seed", &seed, "S", "random seed (default 0)", 0, 1 << 30)
        .option("threads", &threads, "N", "worker threads (default: all cores)", 0, 1024)
        .option("backend", "auto|cpu|cuda", "where paths are traced (default cpu; auto: CUDA when a device exists)",
                [&](const std::string& v) { backend = parse_backend_request(v); })
        .flag("quiet", &quiet, "print nothing on success");
    args.short_name('o', "output").short_name('n', "photons");
    args.parse(argc, argv);
    return cli::run_tool("kdpm-shoot-photons", [&] {
        if (output.empty()) throw std::invalid_argument("no output file (use -o FILE.kdph)");
        const std::filesystem::path inputs[] = {input};
        check_output_destination(output, inputs);
        ThreadLimit limit(threads);
        auto geometry = GeometryFile::open(input);  // checksums verified on open
        const auto& info = geometry.info();
        ShootOptions options;
        options.photons = photons > 0 ? static_cast<std::uint64_t>(photons)
                                      : (info.default_photons > 0 ? info.default_photons : 262144u);
        options.max_bounces = bounces >= 0 ? static_cast<std::uint32_t>(bounces)
                                           : (info.default_bounces > 0 && info.default_bounces <= 255 ? info.default_bounces : 4u);
        options.seed = static_cast<std::uint32_t>(seed);
        const PathRange range = paths.empty() ? PathRange{0, options.photons} : parse_path_range(paths, options.photons);
        options.path_begin = range.begin;
        options.path_end = range.end;
        const BackendSelection selected = select_backend(backend);
        if (!selected.notice.empty() && !quiet) std::cerr << "kdpm-shoot-photons: " << selected.notice << "\n";
        options.backend = selected.kind;
        // The CUDA context is made before the clock starts: its start-up is the process's, not the shot's.
        const double device_start_ms = selected.kind == BackendKind::cuda ? start_cuda_device() : 0.0;

        auto start = std::chrono::steady_clock::now();
        ShotPhotons shot = [&] {
            cli::Progress progress("shooting photons", quiet);
            auto s = shoot_photons(geometry.view(), options, [&](double f) { progress.update(f); });
            progress.finish();
            return s;
        }();
        double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        PhotonHitSet set{shot.info, std::move(shot.hits)};
        Metadata meta;
        meta.tool = "kdpm-shoot-photons";
        meta.tool_version = kdpm_version();
        meta.source_path = std::filesystem::path(input).filename().string();
        meta.source_hash = hash_file(input);
        meta.parameters["photons"] = std::to_string(options.photons);
        meta.parameters["bounces"] = std::to_string(options.max_bounces);
        meta.parameters["seed"] = std::to_string(options.seed);
        meta.parameters[kPathsParameter] = path_range_text(range);
        meta.parameters["store_direct"] = "true";
        meta.statistics["stored"] = set.info.stored_count;
        meta.statistics["caustic"] = set.info.caustic_count;
        meta.statistics["rays"] = static_cast<double>(shot.rays);
        photon_hits_writer(set, meta).write(output);

        if (!quiet) {
            std::uint32_t direct = 0;
            for (const auto& h : set.hits) direct += photon_bounce(h.flags) == 0;
            const std::string shard = paths.empty() ? "" : "paths " + path_range_text(range) + " of ";
            char device[64] = "";
            if (selected.kind == BackendKind::cuda)
                std::snprintf(device, sizeof device, " on CUDA after a %.0f ms device start", device_start_ms);
            std::printf("kdpm-shoot-photons: %s%llu emitted, %u stored (global map %u, caustic map %u; %u direct hits), "
                        "%llu rays, %.2f s%s (%.2f M rays/s) -> %s\n",
                        shard.c_str(), static_cast<unsigned long long>(options.photons), set.info.stored_count,
                        set.info.stored_count, set.info.caustic_count, direct,
                        static_cast<unsigned long long>(shot.rays), secs, device, shot.rays / secs * 1e-6, output.c_str());
        }
        return 0;
    });
}
