// kdpm-shoot-photons SCENE.kdg -n COUNT --bounces B -o PHOTONS.kdph: traces photon paths from the
// scene's area lights and stores every diffuse hit (with its bounce index and caustic flag).
// --paths BEGIN:END traces only those paths of the COUNT, a shard for kdpm-merge-photons.
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>

#include "builders/photons/photon_shards.h"
#include "runtime/backend/backend_kind.h"
#include "runtime/backend/cuda_device.h"
#include "runtime/backend/thread_limit.h"
#include "tools/cli/args.h"
#include "tools/cli/progress.h"
#include "tools/cli/run_tool.h"
#include "tools/jobs/photon_jobs.h"

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
        ThreadLimit limit(threads);
        ShootJob job;
        job.photons = static_cast<std::uint64_t>(photons);
        job.bounces = bounces;
        job.seed = static_cast<std::uint32_t>(seed);
        job.paths = paths;
        const BackendSelection selected = select_backend(backend);
        if (!selected.notice.empty() && !quiet) std::cerr << "kdpm-shoot-photons: " << selected.notice << "\n";
        job.backend = selected.kind;
        // The CUDA context is made before the shot's clock starts: its start-up is the process's.
        const double device_start_ms = selected.kind == BackendKind::cuda ? start_cuda_device() : 0.0;
        const ShootJobResult shot = [&] {
            cli::Progress progress("shooting photons", quiet);
            auto s = shoot_photons_job(input, output, job, [&](double f) { progress.update(f); });
            progress.finish();
            return s;
        }();

        if (!quiet) {
            const std::string shard = paths.empty() ? "" : "paths " + path_range_text(shot.range) + " of ";
            char device[64] = "";
            if (selected.kind == BackendKind::cuda)
                std::snprintf(device, sizeof device, " on CUDA after a %.0f ms device start", device_start_ms);
            std::printf("kdpm-shoot-photons: %s%llu emitted, %u stored (global map %u, caustic map %u; %u direct hits), "
                        "%llu rays, %.2f s%s (%.2f M rays/s) -> %s\n",
                        shard.c_str(), static_cast<unsigned long long>(shot.emitted), shot.info.stored_count,
                        shot.info.stored_count, shot.info.caustic_count, shot.direct_hits,
                        static_cast<unsigned long long>(shot.rays), shot.seconds, device,
                        shot.rays / shot.seconds * 1e-6, output.c_str());
        }
        return 0;
    });
}
