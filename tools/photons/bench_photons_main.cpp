// kdpm-bench-photons [SCENE ...]: photon shooting speed (beside the bench's Embree photon tracer
// on the same paths, when Embree is installed), then k-nearest-photon queries per second
// at the camera's primary hit points for k = 2, 4, ..., 256 on the VVH tree, the balanced tree
// and nanoflann over the same photons, side by side. The trees are queried as the renderer
// queries them: written as .kdp files and memory-mapped by PhotonMapFile. nanoflann is optional
// (compiled in when its headers are installed). SCENE: a .kdg file or a scene card (.json);
// default: the project's Cornell box, Sponza and Conference cards (those whose mesh is present).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <ctime>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/scene_card.h"
#include "builders/photons/photon_tree_builder.h"
#include "builders/photons/photon_tree_writer.h"
#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/knn_search.h"
#include "runtime/photons/photon_map_file.h"
#include "runtime/photons/photon_shooter.h"
#include "tools/cli/args.h"
#include "tools/cli/run_tool.h"
#include "tools/photons/primary_hits.h"
#if defined(KDPM_HAVE_NANOFLANN)
#include "tools/bench/peer_nanoflann.h"
#endif
#if defined(KDPM_HAVE_EMBREE)
#include "tools/bench/peer_embree_photons.h"
#include "tools/bench/photon_agreement.h"
#endif

using namespace kdpm;
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::optional<GeometryFile> load_geometry(const fs::path& input) {
    if (input.extension() == ".kdg") return GeometryFile::open(input);
    if (is_scene_card(input) && !fs::exists(card_mesh_path(input))) {
        std::printf("%s: skipped (mesh %s not found)\n", input.filename().string().c_str(),
                    card_mesh_path(input).string().c_str());
        return std::nullopt;
    }
    auto build = build_geometry_file(load_scene_input(input), KdBuildParams{});
    auto bytes = build.writer.bytes();
    return GeometryFile::from_bytes(bytes, input.filename().string());
}

// The tree as the renderer gets it: written to a .kdp file and mapped (the mapping outlives the
// file, which is removed at once).
PhotonMapFile as_mapped_file(const BuiltPhotonTree& tree, const std::string& name) {
    ContainerWriter writer(FileKind::photon_tree);
    add_photon_tree_sections(writer, PhotonMapKind::global, tree);
    writer.set_metadata(Metadata{});
    const fs::path path = fs::temp_directory_path() / ("kdpm-bench-photons-" + std::to_string(::getpid()) + "-" + name + ".kdp");
    writer.write(path);
    try {
        PhotonMapFile file = PhotonMapFile::open(path);
        fs::remove(path);
        return file;
    } catch (...) {
        fs::remove(path);
        throw;
    }
}

// Queries per second of body(i) over n queries: with one thread, on this thread and timed by its
// CPU clock (steadier on a shared machine); otherwise on all workers by the wall clock.
template <class Body>
double queries_per_second(std::size_t n, const Body& body, bool single_thread) {
    if (single_thread) {
        timespec t0{}, t1{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
        for (std::size_t i = 0; i < n; ++i) body(i);
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
        return n / ((t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec));
    }
    auto start = Clock::now();
    cpu_parallel_for(n, body);
    return n / seconds_since(start);
}

struct BenchOptions {
    int photons = 0, bounces = 4, size = 512, leaf_size = 0;  // 0: each builder's default
    int k_min = 2, k_max = 256, repeat = 3;
    int threads = 1;  // Embree's build workers
    bool nanoflann = true, embree = true;
    bool single_thread = false;
};

void bench_scene(const fs::path& input, const BenchOptions& o) {
    auto geometry = load_geometry(input);
    if (!geometry) return;
    const std::string name = input.stem().string();

    ShootOptions shoot;
    shoot.photons = o.photons > 0 ? static_cast<std::uint64_t>(o.photons)
                                  : (geometry->info().default_photons ? geometry->info().default_photons : 262144u);
    shoot.max_bounces = static_cast<std::uint32_t>(o.bounces);
    auto t0 = Clock::now();
    ShotPhotons shot = shoot_photons(geometry->view(), shoot);
    double shoot_s = seconds_since(t0);
    std::printf("%s: shot %llu photons in %.3f s: %.2f M photons/s, %zu stored, %.2f M rays/s\n", name.c_str(),
                static_cast<unsigned long long>(shoot.photons), shoot_s, shoot.photons / shoot_s * 1e-6,
                shot.hits.size(), shot.rays / shoot_s * 1e-6);
#if defined(KDPM_HAVE_EMBREE)
    if (o.embree) {
        // The same paths through the bench's Embree photon tracer (kdpm's shooter over rtcIntersect1).
        const bench::EmbreePhotonTracer tracer(geometry->view(), o.threads);
        t0 = Clock::now();
        const ShotPhotons theirs = tracer.shoot(shoot);
        const double embree_s = seconds_since(t0);
        float extent = 0.0f;
        for (int a = 0; a < 3; ++a)
            extent = std::max(extent, geometry->info().bounds_max[a] - geometry->info().bounds_min[a]);
        const bench::PhotonAgreement agree = bench::compare_photons(shot.hits, theirs.hits, 1e-5f * extent);
        std::printf("  Embree photon tracer: %.3f s (kdpm / Embree %.2fx), %zu stored (%llu caustic, kdpm %llu); "
                    "%.4f of paths stored the same hits\n",
                    embree_s, shoot_s / embree_s, theirs.hits.size(), (unsigned long long)agree.theirs_caustic,
                    (unsigned long long)agree.ours_caustic, agree.path_agreement());
    }
#endif

    PhotonTreeOptions vvh_options, balanced_options;
    vvh_options.leaf_size = balanced_options.leaf_size = static_cast<std::uint32_t>(o.leaf_size);
    balanced_options.builder = PhotonTreeBuilder::balanced;
    t0 = Clock::now();
    BuiltPhotonTree vvh = build_photon_tree(shot.hits, vvh_options, shot.info.emitted_count, shot.info.max_bounces);
    double vvh_s = seconds_since(t0);
    t0 = Clock::now();
    BuiltPhotonTree balanced = build_photon_tree(shot.hits, balanced_options, shot.info.emitted_count, shot.info.max_bounces);
    double balanced_s = seconds_since(t0);
    double flann_s = 0.0;
#if defined(KDPM_HAVE_NANOFLANN)
    std::optional<bench::NanoflannPeer> flann;
    if (o.nanoflann) {
        flann.emplace(vvh.x, vvh.y, vvh.z);  // the photon positions, in any order
        flann_s = flann->build_ms() * 1e-3;
    }
#else
    const bool flann = false;
#endif
    std::printf("  trees: VVH %u nodes, depth %u, r %.4g, %.3f s | balanced %u nodes, depth %u, %.3f s | "
                "nanoflann (leaf 10) %.3f s\n",
                vvh.info.node_count, vvh.info.max_depth, vvh.info.query_radius, vvh_s, balanced.info.node_count,
                balanced.info.max_depth, balanced_s, flann_s);

    auto points = photon_tools::primary_hits(*geometry, static_cast<std::uint32_t>(o.size), static_cast<std::uint32_t>(o.size));
    std::printf("  queries: %zu primary hits of %dx%d pixels\n", points.size(), o.size, o.size);
    if (points.empty()) return;
    std::printf("  %5s %14s %14s %14s %12s %12s %9s\n", "k", "VVH q/s", "balanced q/s", "nanoflann q/s",
                "VVH/bal time", "VVH/nf time", "agree");

    const PhotonMapFile vvh_file = as_mapped_file(vvh, "vvh"), balanced_file = as_mapped_file(balanced, "balanced");
    const PhotonMapView vvh_view = vvh_file.view(), balanced_view = balanced_file.view();
    std::vector<float> queries;
    for (const SurfacePoint& p : points) queries.insert(queries.end(), {p.position.x, p.position.y, p.position.z});
    std::vector<float> kth_vvh(points.size()), kth_bal(points.size()), kth_nf(points.size());
    for (int k = o.k_min; k <= o.k_max; k *= 2) {
        const auto uk = static_cast<std::uint32_t>(k);
        auto tree_query = [&](const PhotonMapView& view, std::vector<float>& kth) {
            return [&, uk](std::uint64_t i) {
                KnnHeap heap;
                std::uint32_t n = knn_search(view, points[i].position, uk, 0.0f, heap);
                kth[i] = n ? heap.d2[0] : 0.0f;
            };
        };
        double q_vvh = 0.0, q_bal = 0.0, q_nf = 0.0;
        for (int rep = 0; rep < o.repeat; ++rep) {
            q_vvh = std::max(q_vvh, queries_per_second(points.size(), tree_query(vvh_view, kth_vvh), o.single_thread));
            q_bal = std::max(q_bal, queries_per_second(points.size(), tree_query(balanced_view, kth_bal), o.single_thread));
#if defined(KDPM_HAVE_NANOFLANN)
            if (flann) {
                const auto start = Clock::now();
                flann->knn(queries, k, kth_nf);
                q_nf = std::max(q_nf, points.size() / seconds_since(start));
            }
#endif
        }
        std::size_t agree = 0;
        for (std::size_t i = 0; i < points.size(); ++i)
            agree += kth_vvh[i] == kth_bal[i] &&
                     (!flann || std::fabs(kth_vvh[i] - kth_nf[i]) <= 1e-6f * std::max(kth_vvh[i], 1e-30f));
        std::printf("  %5d %14.0f %14.0f %14.0f %12.2f %12.2f %8.2f%%", k, q_vvh, q_bal, q_nf, q_bal / q_vvh,
                    flann ? q_nf / q_vvh : 0.0, 100.0 * agree / points.size());
        std::printf("\n");
        std::fflush(stdout);
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> scenes;
    std::string extra1, extra2, extra3;
    BenchOptions o;
    int threads = 0;
    bool no_nanoflann = false, no_embree = false;
    cli::Args args("kdpm-bench-photons",
                   "Photon shooting speed and kNN gather queries/s (VVH vs balanced vs nanoflann) at primary hits.");
    args.positional("SCENE", &extra1, "a .kdg file or scene card (default: Cornell box, Sponza, Conference)", false)
        .positional("SCENE2", &extra2, "another scene", false)
        .positional("SCENE3", &extra3, "another scene", false)
        .option("photons", &o.photons, "N", "photon paths to shoot (default: the scene's, else 262144)", 0, 1 << 28)
        .option("bounces", &o.bounces, "B", "most bounces (default 4)", 0, 255)
        .option("size", &o.size, "PIXELS", "image width and height for the query points (default 512)", 1, 8192)
        .option("leaf-size", &o.leaf_size, "N", "photon tree leaf size (default " + std::to_string(kVvhLeafSize) + " for VVH, " +
                    std::to_string(kBalancedLeafSize) + " for the balanced tree)",
                1,
                4096)
        .option("k-max", &o.k_max, "K", "largest k (default 256; k = 2, 4, 8, ... up to it)", 2, 256)
        .option("k-min", &o.k_min, "K", "smallest k (default 2)", 1, 256)
        .option("repeat", &o.repeat, "N", "runs per measurement, the fastest counts (default 3)", 1, 100)
        .option("threads", &threads, "N", "worker threads (default: all cores)", 0, 1024)
        .flag("no-nanoflann", &no_nanoflann, "skip the nanoflann reference")
        .flag("no-embree", &no_embree, "skip the Embree photon tracer");
    args.parse(argc, argv);
    o.nanoflann = !no_nanoflann;
    o.embree = !no_embree;
    o.threads = threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency());
    o.single_thread = threads == 1;
    return cli::run_tool("kdpm-bench-photons", [&] {
        ThreadLimit limit(threads);
        for (auto* s : {&extra1, &extra2, &extra3})
            if (!s->empty()) scenes.push_back(*s);
        if (scenes.empty())
            for (const char* card : {"scenes/cornell-box/cornell-box.json", "scenes/sponza/sponza.json",
                                     "scenes/conference/conference.json"})
                scenes.push_back(std::string(KDPM_SOURCE_DIR) + "/" + card);
        for (const auto& s : scenes) bench_scene(s, o);
        return 0;
    });
}
