#include "tools/bench/scene_bench.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <functional>
#include <thread>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/scene_card.h"
#include "builders/photons/photon_map_writer.h"
#include "runtime/backend/backend_kind.h"
#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/backend/cuda_device.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/photons/knn_search.h"
#include "runtime/photons/photon_map_file.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/photons/radius_hints.h"
#include "runtime/render/camera.h"
#include "runtime/render/passes/camera_packet_pass.h"
#include "runtime/render/renderer.h"
#include "runtime/render/scene_loader.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"
#include "runtime/shading/ray_offset.h"
#include "tools/bench/camera_packets.h"
#include "tools/bench/median_time.h"
#include "tools/bench/peer_embree.h"
#include "tools/bench/peer_embree_photons.h"
#include "tools/bench/peer_nanoflann.h"
#include "tools/photons/irradiance_step.h"

namespace kdpm::bench {
namespace {

void say(const SceneBenchConfig& c, const std::string& what) {
    if (!c.quiet) std::fprintf(stderr, "  [%s] %s\n", c.name.c_str(), what.c_str());
}

// Pairs of passes for the ray rows, whose passes take milliseconds: with seven, the ratio of the
// Conference's fast and high trees on the same rays read 1.05x in a noisy run where 25 pairs in
// a row read 1.02x (quartiles 1.01-1.03x); fifteen cost about a second more a scene.
constexpr int kShortPassPairs = 15;
// Three builds (ours high and fast, Embree HQ) shorter than this together are timed in as many
// rounds as a short pass.
constexpr double kShortBuildsMs = 10.0;

std::string fmt_grid(std::uint32_t n) { return std::to_string(n) + " x " + std::to_string(n); }

std::string thread_label(int t) { return std::to_string(t) + (t == 1 ? " thread" : " threads"); }

// The report's frame table on one backend: ray tracing alone (the trace stage of every frame)
// and ray tracing + gather for each k.
FrameTable measure_frames(const SceneBenchConfig& c, Renderer& renderer, std::string label) {
    FrameTable table;
    table.label = std::move(label);
    std::vector<double> trace;
    for (int k : c.ks) {
        std::vector<double> with_gather;
        RenderSettings s;
        s.width = c.width;
        s.height = c.height;
        s.mode = RenderMode::photons;
        s.k = static_cast<std::uint32_t>(k);
        renderer.render(s);  // warm-up: caches, device buffers
        for (int f = 0; f < c.frames; ++f) {
            RenderResult r = renderer.render(s);
            trace.push_back(r.times.ray_tracing_ms);
            with_gather.push_back(r.times.ray_tracing_ms + r.times.photon_gather_ms);
        }
        table.with_gather_ms[k] = median_of(with_gather);
    }
    table.ray_tracing_ms = median_of(trace);
    return table;
}

// Rays traced through both intersectors, kdpm's hits, and the points they hit (camera rays).
struct TracedRays {
    std::vector<PeerRay> rays;
    std::vector<Hit> hits;
    std::vector<float> hit_points;  // 3 floats per ray that hit something
};

TracedRays primary_rays(const CameraRecord& camera, std::uint32_t width, std::uint32_t height) {
    TracedRays p;
    auto cam = PinholeCamera::from_record(camera, width, height, 1);
    p.rays.resize(static_cast<std::size_t>(width) * height);
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            CameraRay r = cam.ray(x, y, 0);
            p.rays[y * width + x] = {{r.origin.x, r.origin.y, r.origin.z}, {r.direction.x, r.direction.y, r.direction.z}};
        }
    return p;
}

double trace_with_kdpm(const GeometryView& g, TracedRays& p) {
    p.hits.resize(p.rays.size());
    return median_ms(1, [&] {
        cpu_parallel_for(p.rays.size(), [&](std::uint64_t i) {
            const PeerRay& r = p.rays[i];
            Ray ray{glm::vec3(r.origin[0], r.origin[1], r.origin[2]), 0.0f,
                    glm::vec3(r.direction[0], r.direction[1], r.direction[2]), INFINITY};
            p.hits[i] = closest_hit(g, ray);
        }, 256);
    });
}

// The two qualities' trees on the same primary rays, passes interleaved so that both see the
// same machine; hits must agree (exact trees differ at most in ties).
void compare_qualities(const SceneBenchConfig& c, const GeometryFile& fast, const GeometryFile& high,
                       SceneBenchResult& out) {
    TracedRays pf = primary_rays(fast.camera(), c.width, c.height), ph = pf;
    std::vector<double> fast_ms, high_ms;
    // Short passes on a drifting host: kShortPassPairs at least, as the peer ray rows.
    for (int f = 0; f < std::max(c.frames, kShortPassPairs) + 1; ++f) {
        fast_ms.push_back(trace_with_kdpm(fast.view(), pf));
        high_ms.push_back(trace_with_kdpm(high.view(), ph));
    }
    fast_ms.erase(fast_ms.begin());  // warm-up
    high_ms.erase(high_ms.begin());
    out.quality.rays = paired_times(fast_ms, high_ms);
    std::size_t same = 0;
    for (std::size_t i = 0; i < pf.hits.size(); ++i)
        same += pf.hits[i].found() == ph.hits[i].found() && (!pf.hits[i].found() || pf.hits[i].t == ph.hits[i].t);
    out.quality.same_hits = pf.hits.empty() ? 1.0 : static_cast<double>(same) / pf.hits.size();
}

#ifdef KDPM_HAVE_EMBREE
// Fraction of rays whose hit agrees with ours: same triangle, or the same distance (ties).
double same_hit_fraction(const std::vector<Hit>& ours, const std::vector<PeerHit>& theirs) {
    std::size_t same = 0;
    for (std::size_t i = 0; i < theirs.size(); ++i) {
        bool ours_hit = ours[i].found(), theirs_hit = theirs[i].triangle != 0xffffffffu;
        if (ours_hit == theirs_hit &&
            (!ours_hit || ours[i].triangle == theirs[i].triangle ||
             std::fabs(ours[i].t - theirs[i].t) <= 1e-4f * std::max(1.0f, theirs[i].t)))
            ++same;
    }
    return theirs.empty() ? 1.0 : static_cast<double>(same) / theirs.size();
}

// A cosine-distributed ray leaving each stored hit on the side the photon came from, in the
// hits' path order: the incoherent single rays photon shooting traces after a diffuse bounce.
TracedRays bounce_rays(const std::vector<PhotonHit>& hits, float ray_offset) {
    TracedRays b;
    b.rays.resize(hits.size());
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const PhotonHit& h = hits[i];
        const glm::vec3 n(h.normal[0], h.normal[1], h.normal[2]);
        const glm::vec3 d = cosine_direction(n, counter_random(7, i, 0, 0), counter_random(7, i, 0, 1));
        const glm::vec3 o = offset_origin(glm::vec3(h.position[0], h.position[1], h.position[2]), n, ray_offset, true);
        b.rays[i] = {{o.x, o.y, o.z}, {d.x, d.y, d.z}};
    }
    return b;
}

// kdpm's shooter and the Embree photon tracer (the same shooter over rtcIntersect1) on the same
// paths, runs interleaved so that both see the same machine; then whether they stored the same.
// Then the bounce rays of kdpm's hits through both intersectors (embree: its last build).
void compare_photon_tracers(const SceneBenchConfig& c, const GeometryView& g, const EmbreePeer& embree,
                            PeerFigures& peers) {
    say(c, "Embree photon tracer: the same photon paths");
    EmbreePhotonTracer tracer(g, static_cast<int>(std::thread::hardware_concurrency()));
    ShootOptions shoot;
    shoot.photons = c.photons;
    shoot.max_bounces = c.bounces;
    ShotPhotons ours, theirs;
    std::vector<double> ours_ms, theirs_ms;
    // A shooting pass takes a tenth of a second or two, short enough for a drifting host to move
    // single pairs by a fifth either way (a lab run's Sponza pairs: 0.81-1.07x around 1.00x): as
    // many pairs as the ray rows.
    for (int f = 0; f < std::max(c.frames, kShortPassPairs); ++f) {
        ours_ms.push_back(median_ms(1, [&] { ours = shoot_photons(g, shoot); }));
        theirs_ms.push_back(median_ms(1, [&] { theirs = tracer.shoot(shoot); }));
    }
    peers.shoot = paired_times(ours_ms, theirs_ms);
    float extent = 0.0f;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, g.info.bounds_max[a] - g.info.bounds_min[a]);
    peers.photon_agreement = compare_photons(ours.hits, theirs.hits, 1e-5f * extent);

    TracedRays b = bounce_rays(ours.hits, photon_ray_offset(g.info));
    std::vector<PeerHit> their_hits(b.rays.size());
    std::vector<double> ours_b, theirs_b;
    for (int f = 0; f < std::max(c.frames, kShortPassPairs); ++f) {  // short passes, as the primary rays
        ours_b.push_back(trace_with_kdpm(g, b));
        theirs_b.push_back(median_ms(1, [&] { embree.intersect(b.rays, their_hits); }));
    }
    peers.bounce_rays = b.rays.size();
    peers.bounce = paired_times(ours_b, theirs_b);
    peers.bounce_ray_agreement = same_hit_fraction(b.hits, their_hits);
}
#endif

// kdpm's offline stages on this scene's inputs, with all threads, for timing beside their peers.
struct KdpmStages {
    std::function<void()> build_high, build_fast, photon_trees;
};

void compare_peers(const SceneBenchConfig& c, const GeometryFile& geometry, const PhotonMaps& maps,
                   const KdpmStages& stages, SceneBenchResult& out) {
    const PhotonMapView& photons = maps.global;
    PeerFigures& peers = out.peers;
    TracedRays p = primary_rays(geometry.camera(), c.width, c.height);
    const GeometryView& g = geometry.view();

    // Our rays, single and in packets: a first pass each for the hits (and to warm up); with
    // Embree the timings come from the pairs below, without it from passes of their own.
    std::vector<Hit> kdpm_packet_hits;
    const PinholeCamera camera = PinholeCamera::from_record(geometry.camera(), c.width, c.height, 1);  // primary_rays' camera
    (void)trace_with_kdpm(g, p);
    (void)trace_camera_packets(g, camera, kdpm_packet_hits);
#ifndef KDPM_HAVE_EMBREE
    std::vector<double> ours, packets;
    for (int f = 0; f < c.frames; ++f) {
        ours.push_back(trace_with_kdpm(g, p));
        packets.push_back(trace_camera_packets(g, camera, kdpm_packet_hits));
    }
    peers.rays.ours_ms = median_of(ours);
    peers.packets.ours_ms = median_of(packets);
#endif
    std::size_t same_as_single = 0;
    for (std::size_t i = 0; i < kdpm_packet_hits.size(); ++i)
        same_as_single += std::memcmp(&kdpm_packet_hits[i], &p.hits[i], sizeof(Hit)) == 0;
    peers.packet_same_as_single =
        kdpm_packet_hits.empty() ? 1.0 : static_cast<double>(same_as_single) / kdpm_packet_hits.size();
    for (std::size_t i = 0; i < p.rays.size(); ++i)
        if (p.hits[i].found()) {
            const PeerRay& r = p.rays[i];
            for (int a = 0; a < 3; ++a) p.hit_points.push_back(r.origin[a] + p.hits[i].t * r.direction[a]);
        }
    out.primary_hits = p.hit_points.size() / 3;

#ifdef KDPM_HAVE_EMBREE
    {
        say(c, "Embree: medium- and high-quality BVH builds, rtcIntersect1 and rtcIntersect16");
        std::vector<float> vertices;
        vertices.reserve(g.triangle_count * 9);
        for (std::uint32_t t = 0; t < g.triangle_count; ++t) {
            const TriangleRecord& tr = g.triangles[t];
            for (int a = 0; a < 3; ++a) vertices.push_back(tr.v0[a]);
            for (int a = 0; a < 3; ++a) vertices.push_back(tr.v0[a] + tr.e1[a]);
            for (int a = 0; a < 3; ++a) vertices.push_back(tr.v0[a] + tr.e2[a]);
        }
        EmbreePeer embree(vertices, static_cast<int>(std::thread::hardware_concurrency()));
        (void)embree.build_ms();  // warm-up: Embree starts its threads on the first build
        std::vector<double> medium, builds, ours_high, ours_fast;
        for (int f = 0; f < c.frames; ++f) medium.push_back(embree.build_ms(EmbreeBuildQuality::medium));
        peers.embree_medium_build_ms = median_of(medium);
        // Our builds and Embree's high-quality one in turn, so that each round sees one machine
        // (the host's speed drifts by tens of percent within a run); Embree's last: rtcIntersect1
        // below traces through it.
        // Builds of a few milliseconds or less (the Cornell box's take tens of microseconds, where
        // a cache miss more or less is a tenth) get as many rounds as the short ray passes.
        int rounds = c.frames;
        for (int f = 0; f < rounds; ++f) {
            ours_high.push_back(median_ms(1, stages.build_high));
            ours_fast.push_back(median_ms(1, stages.build_fast));
            builds.push_back(embree.build_ms(EmbreeBuildQuality::high));
            if (f == 0 && ours_high[0] + ours_fast[0] + builds[0] < kShortBuildsMs)
                rounds = std::max(c.frames, kShortPassPairs);
        }
        peers.build_high = paired_times(ours_high, builds);
        peers.build_fast = paired_times(ours_fast, builds);
        std::vector<PeerHit> hits(p.rays.size());
        std::vector<PeerHit> packet_hits(p.rays.size());
        embree.intersect(p.rays, hits);  // warm-up
        embree.intersect16(p.rays, c.width, c.height, packet_hits);
        // The ray rows again, each of our passes followed by Embree's on the same rays, so that a
        // pair sees the same machine (the host's speed drifts by tens of percent within a run);
        // these short passes take at least kShortPassPairs pairs.
        std::vector<double> ours1, theirs1, ours16, theirs16;
        for (int f = 0; f < std::max(c.frames, kShortPassPairs); ++f) {
            ours1.push_back(trace_with_kdpm(g, p));
            theirs1.push_back(median_ms(1, [&] { embree.intersect(p.rays, hits); }));
            ours16.push_back(trace_camera_packets(g, camera, kdpm_packet_hits));
            theirs16.push_back(median_ms(1, [&] { embree.intersect16(p.rays, c.width, c.height, packet_hits); }));
        }
        peers.rays = paired_times(ours1, theirs1);
        peers.packets = paired_times(ours16, theirs16);
        peers.ray_agreement = same_hit_fraction(p.hits, hits);
        // packet_hits: the same rays as 16-ray packets of 4x4 pixel tiles (row-major order).
        peers.packet_agreement = same_hit_fraction(p.hits, packet_hits);
        peers.embree = true;
        compare_photon_tracers(c, g, embree, peers);
    }
#endif

    // kNN at the primary hit points: ours and (when present) nanoflann's, same photons.
    const std::size_t queries = p.hit_points.size() / 3;
    std::vector<float> ours_kth(queries), plain_kth(queries), theirs_kth(queries);
    // As the renderer gathers: runs of 64 consecutive queries (a row segment of the image), each
    // search started from the radius hints of the queries before it in the run (search_from_hint).
    constexpr std::uint64_t kRun = 64;
    auto run_ours = [&](int k) {
        const auto kk = static_cast<std::uint32_t>(k);
        cpu_parallel_for((queries + kRun - 1) / kRun, [&](std::uint64_t run) {
            KnnHeap heap;
            RadiusHints hints;
            for (std::uint64_t q = run * kRun; q < std::min<std::uint64_t>(queries, (run + 1) * kRun); ++q) {
                const glm::vec3 point(p.hit_points[3 * q], p.hit_points[3 * q + 1], p.hit_points[3 * q + 2]);
                auto search = [&](float limit) {
                    return knn_search(photons, point, kk, limit, EuclideanMetric{}, AcceptAll{}, heap);
                };
                const std::uint32_t n = search_from_hint(search, kk, hints.hint(point), 0.0f);
                if (n == kk) hints.remember(point, std::sqrt(heap.d2[0]));
                ours_kth[q] = n ? heap.d2[0] : 0.0f;
            }
        }, 1);
    };
    // Each query on its own from the root, as a caller without neighbours would search.
    auto run_plain = [&](int k) {
        cpu_parallel_for(queries, [&](std::uint64_t q) {
            KnnHeap heap;
            glm::vec3 point(p.hit_points[3 * q], p.hit_points[3 * q + 1], p.hit_points[3 * q + 2]);
            std::uint32_t n = knn_search(photons, point, static_cast<std::uint32_t>(k), 0.0f, EuclideanMetric{},
                                         AcceptAll{}, heap);
            plain_kth[q] = n ? heap.d2[0] : 0.0f;
        }, 64);
    };
#ifdef KDPM_HAVE_NANOFLANN
    const bool paired_knn = photons.photon_count > 0;  // timed beside nanoflann's below
#else
    const bool paired_knn = false;
#endif
    for (int k : c.ks) {
        run_ours(k);
        if (!paired_knn) peers.knn[k].ours_ms = median_ms(c.frames, [&] { run_ours(k); });
        peers.kdpm_plain_knn_ms[k] = median_ms(c.frames, [&] { run_plain(k); });
    }
#ifdef KDPM_HAVE_NANOFLANN
    if (paired_knn) {
        say(c, "nanoflann: k-nearest queries at the same points");
        // nanoflann's kd-tree build over the photons of both maps, as kdpm-build-photons builds both.
        auto peer_of = [](const PhotonMapView& m) {
            return NanoflannPeer({m.x, m.photon_count}, {m.y, m.photon_count}, {m.z, m.photon_count});
        };
        std::vector<double> builds, ours;
        for (int f = 0; f < c.frames; ++f) {  // ours and theirs in turn, as the geometry builds
            ours.push_back(median_ms(1, stages.photon_trees));
            double ms = peer_of(photons).build_ms();
            if (maps.caustic.photon_count > 0) ms += peer_of(maps.caustic).build_ms();
            builds.push_back(ms);
        }
        peers.photon_trees = paired_times(ours, builds);
        NanoflannPeer nano = peer_of(photons);
        // Each of our passes followed by nanoflann's on the same queries: a pair sees the same machine.
        for (int k : c.ks) {
            nano.knn(p.hit_points, k, theirs_kth);
            std::vector<double> ours, theirs;
            for (int f = 0; f < c.frames; ++f) {
                ours.push_back(median_ms(1, [&] { run_ours(k); }));
                theirs.push_back(median_ms(1, [&] { nano.knn(p.hit_points, k, theirs_kth); }));
            }
            peers.knn[k] = paired_times(ours, theirs);
        }
        // Cross-check on the last k: the k-th nearest distance must agree, with and without hints.
        run_ours(c.ks.back());
        run_plain(c.ks.back());
        std::size_t same = 0, plain_same = 0;
        for (std::size_t q = 0; q < queries; ++q) {
            if (std::fabs(ours_kth[q] - theirs_kth[q]) <= 1e-5f * std::max(1e-12f, theirs_kth[q])) ++same;
            if (std::fabs(plain_kth[q] - theirs_kth[q]) <= 1e-5f * std::max(1e-12f, theirs_kth[q])) ++plain_same;
        }
        peers.knn_agreement = queries ? static_cast<double>(same) / queries : 1.0;
        peers.plain_knn_agreement = queries ? static_cast<double>(plain_same) / queries : 1.0;
        peers.nanoflann = true;
    }
#endif
}

}  // namespace

SceneBenchResult run_scene_bench(const SceneBenchConfig& c) {
    SceneBenchResult out;
    out.name = c.name;
    out.build = c.build;
    const auto kdg = c.work_dir / (c.name + ".kdg");
    const auto kdp = c.work_dir / (c.name + ".kdp");

    say(c, "importing " + c.card.string());
    Scene scene = load_scene_input(c.card);
    out.triangles = scene.triangles.size();
    KdBuildParams params = c.build;  // --quality high, the default
    params.quality = KdBuildQuality::high;
    KdBuildParams fast = params;
    fast.quality = KdBuildQuality::fast;

    for (int t : c.threads) {
        say(c, "geometry kd-tree builds (high, fast), " + thread_label(t));
        ThreadLimit limit(t);
        out.geometry_build_ms[t] = median_ms(c.frames, [&] { (void)build_geometry_file(scene, params); });
        out.geometry_build_fast_ms[t] = median_ms(c.frames, [&] { (void)build_geometry_file(scene, fast); });
    }
    GeometryBuild high_build = build_geometry_file(scene, params);
    high_build.writer.write(kdg);
    out.quality.high_sah = high_build.stats.sah_cost;
    out.kdg_bytes = std::filesystem::file_size(kdg);
    GeometryFile geometry = GeometryFile::open(kdg);
    const GeometryBuild fast_build = build_geometry_file(scene, fast);
    out.quality.fast_sah = fast_build.stats.sah_cost;
    const GeometryFile fast_geometry = GeometryFile::from_bytes(fast_build.writer.bytes(), c.name + "-fast.kdg");
    say(c, "primary rays through the fast and the high tree");
    compare_qualities(c, fast_geometry, geometry, out);

    ShootOptions shoot;
    shoot.photons = c.photons;
    shoot.max_bounces = c.bounces;
    ShotPhotons shot;
    for (int t : c.threads) {
        say(c, "photon shooting, " + thread_label(t));
        ThreadLimit limit(t);
        out.shoot_ms[t] = median_ms(1, [&] { shot = shoot_photons(geometry.view(), shoot); });
    }
    out.photons_emitted = shot.info.emitted_count;
    out.photons_stored = shot.hits.size();
    // A device that cannot start is said once, under the frame table; the rest runs on the CPU.
    bool cuda = false;
    if (c.cuda) {
        try {
            (void)select_backend(BackendRequest::cuda);
            (void)start_cuda_device();
            cuda = true;
        } catch (const std::exception& e) {
            out.cuda_note = "no CUDA device (" + std::string(e.what()) + ")";
        }
    }
    if (cuda) {
        // A shot the device fails is said under the frame table; its frames are still tried.
        try {
            say(c, "photon shooting, CUDA");
            ShootOptions on_gpu = shoot;
            on_gpu.backend = BackendKind::cuda;
            (void)shoot_photons(geometry.view(), on_gpu);  // warm-up: the kernels' first load
            out.shoot_cuda_ms = median_ms(c.frames, [&] { (void)shoot_photons(geometry.view(), on_gpu); });
        } catch (const std::exception& e) {
            out.cuda_note = "CUDA photon shooting failed (" + std::string(e.what()) + ")";
        }
    }

    PhotonHitSet set{shot.info, std::move(shot.hits)};
    PhotonTreeOptions vvh;
    for (int t : c.threads) {
        say(c, "photon kd-tree build (VVH), " + thread_label(t));
        ThreadLimit limit(t);
        out.photon_tree_ms[t] = median_ms(c.frames, [&] { (void)build_photon_map_file(set, vvh, {}); });
    }
    PhotonTreeOptions balanced;
    balanced.builder = PhotonTreeBuilder::balanced;
    out.balanced_tree_ms = median_ms(c.frames, [&] { (void)build_photon_map_file(set, balanced, {}); });
    // As kdpm-build-photons writes it: with the irradiance map that final gathering reads.
    build_photon_map_file(set, vvh, {}, default_photon_irradiance()).writer.write(kdp);
    out.kdp_bytes = std::filesystem::file_size(kdp);

    say(c, "loading the files");
    // A load takes milliseconds: as many as the short passes, where three medians moved by half.
    out.load_ms = median_ms(std::max(c.frames, kShortPassPairs), [&] { (void)LoadedScene::load(kdg, kdp); });
    LoadedScene loaded = LoadedScene::load(kdg, kdp);

    for (int t : c.threads) {
        say(c, "frames, " + thread_label(t));
        ThreadLimit limit(t);
        Renderer renderer(loaded.views(), BackendKind::cpu);
        out.frames.push_back(measure_frames(c, renderer, thread_label(t)));
    }
    if (cuda) {
        try {
            say(c, "frames, CUDA");
            Renderer renderer(loaded.views(), BackendKind::cuda);
            out.frames.push_back(measure_frames(c, renderer, "CUDA"));
        } catch (const std::exception& e) {
            out.cuda_note = "CUDA frames failed (" + std::string(e.what()) + ")";
            cuda = false;
        }
    }
    {
        ModeFrameConfig modes;
        modes.width = c.width;
        modes.height = c.height;
        modes.frames = c.frames;
        modes.threads = c.threads.back();
        modes.cuda = cuda;
        modes.say = [&](const std::string& what) { say(c, what); };
        out.mode_frames = measure_mode_frames(loaded.views(), modes);
    }
    const int all = c.threads.back();
    if (c.instance_grid > 0) {
        say(c, fmt_grid(c.instance_grid) + " instances: one as it is, one moved, the grid");
        ThreadLimit limit(all);
        InstanceBenchConfig ic;
        ic.name = c.name;
        ic.object = kdg;
        ic.work_dir = c.work_dir;
        ic.grid_x = ic.grid_z = c.instance_grid;
        ic.width = c.width;
        ic.height = c.height;
        ic.pairs = kShortPassPairs;
        ic.object_build_ms = out.geometry_build_ms[all];
        out.instances = run_instance_bench(ic);
    }
    out.peers.build_high.ours_ms = out.geometry_build_ms[all];
    out.peers.build_fast.ours_ms = out.geometry_build_fast_ms[all];
    out.peers.photon_trees.ours_ms = out.photon_tree_ms[all];
    if (c.peers) {
        // The peers time these again beside their own (all threads), replacing the figures above.
        ThreadLimit limit(all);
        KdpmStages stages;
        stages.build_high = [&] { (void)build_geometry_file(scene, params); };
        stages.build_fast = [&] { (void)build_geometry_file(scene, fast); };
        stages.photon_trees = [&] { (void)build_photon_map_file(set, vvh, {}); };
        compare_peers(c, geometry, loaded.views().photons, stages, out);
    }
    return out;
}

}  // namespace kdpm::bench
