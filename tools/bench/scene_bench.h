#pragma once
// Everything kdpm-bench measures on one scene: the offline builds, the load, the report's frame
// table (ray tracing alone and with the k-nearest gather), and the peers on the same inputs.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "builders/geometry/sah/kd_build_params.h"
#include "tools/bench/instance_bench.h"
#include "tools/bench/median_time.h"
#include "tools/bench/mode_frames.h"
#include "tools/bench/photon_agreement.h"

namespace kdpm::bench {

struct SceneBenchConfig {
    std::string name;              // "cornell-box", "sponza", "conference"
    std::filesystem::path card;    // scene card (or mesh)
    std::filesystem::path work_dir;  // where the .kdg and .kdp are written
    std::vector<int> threads;      // thread counts to measure (e.g. 1 and all)
    std::vector<int> ks;           // k values of the gather table
    int frames = 3;                // frames (or builds) per median
    std::uint32_t width = 512, height = 512;
    std::uint32_t photons = 262144, bounces = 4;
    bool peers = true;
    bool cuda = true;              // measure the CUDA backend when a device exists
    bool quiet = false;
    std::uint32_t instance_grid = 100;  // the instanced grid is N x N copies of the scene; 0: no instance rows
    KdBuildParams build;           // SAH costs of every geometry build (quality: both are built)
};

// Frame figures for one thread count (or the GPU): medians in ms.
struct FrameTable {
    std::string label;                    // "1 thread", "2 threads", "CUDA"
    double ray_tracing_ms = 0;
    std::map<int, double> with_gather_ms;  // k -> ray tracing + gather
};

// kdpm's two geometry build qualities on the same scene (high is the default and the .kdg used).
struct QualityFigures {
    double fast_sah = 0, high_sah = 0;          // SAH cost of the trees
    PairedTimes rays;                           // same primary rays, all threads; ours: fast, peer: high
    double same_hits = 0;                       // fraction of those rays with the same hit distance
};

// kdpm's stages beside their peers, all threads: PairedTimes where timed in pairs.
struct PeerFigures {
    bool embree = false, nanoflann = false;
    PairedTimes build_high, build_fast;                   // kdpm --quality high, fast / Embree HQ BVH
    double embree_medium_build_ms = 0;                    // Embree MEDIUM, timed on its own
    PairedTimes photon_trees;                             // global + caustic trees / nanoflann, same photons
    PairedTimes rays;                                     // same primary rays / rtcIntersect1
    PairedTimes packets;                                  // the same rays as kdpm's 4x4-pixel packets / rtcIntersect16
    double packet_same_as_single = 0;                     // fraction of packet hits equal to the single-ray hits, bit for bit
    double ray_agreement = 0;                             // fraction of rays with the same hit triangle
    double packet_agreement = 0;                          // the same for the packets' hits
    std::map<int, PairedTimes> knn;                       // k -> same queries and photons / nanoflann
    std::map<int, double> kdpm_plain_knn_ms;              // kdpm without radius hints: each query from the root
    double knn_agreement = 0;                             // fraction of queries with the same k-th distance
    double plain_knn_agreement = 0;                       // the same, without radius hints
    // The same photon paths through kdpm's shooter and the Embree photon tracer, all threads.
    PairedTimes shoot;
    PhotonAgreement photon_agreement;
    // Diffuse bounce rays from kdpm's stored hits, in path order (the incoherent rays shooting
    // traces), single rays through both intersectors, all threads; and how many agree.
    std::uint64_t bounce_rays = 0;
    PairedTimes bounce;  // / rtcIntersect1
    double bounce_ray_agreement = 0;
};

struct SceneBenchResult {
    std::string name;
    KdBuildParams build;  // the SAH costs the geometry was built with
    std::uint64_t triangles = 0, photons_emitted = 0, photons_stored = 0, primary_hits = 0;
    std::map<int, double> geometry_build_ms;   // threads -> median, --quality high (the default)
    std::map<int, double> geometry_build_fast_ms;  // threads -> median, --quality fast
    QualityFigures quality;
    std::map<int, double> shoot_ms;            // threads -> one run (deterministic work)
    double shoot_cuda_ms = 0;                  // the same shot on CUDA (median, device started), 0 without one
    std::map<int, double> photon_tree_ms;      // threads -> median (VVH, both maps)
    double balanced_tree_ms = 0;               // all threads, for comparison
    double load_ms = 0;                        // map .kdg + .kdp, until the first frame can start
    std::uint64_t kdg_bytes = 0, kdp_bytes = 0;
    std::vector<FrameTable> frames;
    std::string cuda_note;                     // "no CUDA device" etc.
    PeerFigures peers;
    ModeFrames mode_frames;                    // all threads, each lighting mode
    InstanceFigures instances;                 // the scene as the object of scenes of instances
};

SceneBenchResult run_scene_bench(const SceneBenchConfig& config);

}  // namespace kdpm::bench
