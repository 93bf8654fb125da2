#pragma once
// kdpm-bench-quality on one scene: a converged --mode path reference (cached in the work folder),
// then each lighting mode over a ladder of settings of increasing cost, every rung rendered,
// timed and compared with the reference: error against time.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "runtime/backend/backend_kind.h"
#include "runtime/render/image/image.h"
#include "tools/bench/error_analysis.h"
#include "runtime/render/render_modes.h"

namespace kdpm::bench {

struct QualityConfig {
    std::string name;               // "cornell-box", "sponza", "conference"
    std::filesystem::path card;     // scene card
    std::filesystem::path work_dir; // .kdg, .kdp and the cached references
    std::uint32_t size = 512;       // width and height
    int threads = 2;                // the ladders' thread count (the reference uses every core)
    std::uint32_t reference_spp = 4096;
    BackendRequest reference_backend = BackendRequest::automatic;  // CUDA renders it much sooner
    std::uint32_t max_bounces = 0;  // path reference, path and sppm ladders; 0: unlimited
    std::uint32_t photons = 0;      // photon paths of the .kdp; 0: the scene card's
    int photon_bounces = -1;        // bounces of the .kdp's photons; -1: the scene card's; 0: unlimited
    double seconds = 2.0;           // the equal-time budget of the verdicts and the pictures
    std::vector<double> budgets{1, 2, 4, 8};  // the equal-time table's columns; ladders run past the last
    bool breakdown = false;         // also the gather lookups' ladders (gather_lookup.h): where the bias is
    std::filesystem::path images_dir;  // test | reference | error per ladder (empty: none)
    double sppm_seconds = 30.0;     // the sppm curve runs until a rung takes this long
    int max_rungs = 12;             // per ladder
    std::function<void(const std::string&)> say;  // progress lines (may be empty)
    bool progress_bar = false;      // the reference render's bar (a terminal)
};

struct Rung {
    std::string setting;                 // "4 spp", "64 gather rays", "16 passes"
    double seconds = 0;                  // wall time of the render
    double relmse = 0;                   // against the reference
    double mean_ratio = 0;               // image mean / reference mean
    std::array<double, 3> third_ratio{}; // the same per horizontal third, top to bottom
    RegionSplit regions;                 // near edges and flat (error_analysis.h)
};

// A ladder's label: the mode's name (render_modes.h), then the variant ("final-gather + cache").
inline std::string ladder_label(RenderMode mode, const std::string& variant = {}) {
    return render_mode_name(mode) + variant;
}
inline const std::string kCachedGather = " + cache", kUncachedGather = ", no cache";
inline const std::string kEstimateLookup = " + cache, estimate lookup", kPathLookup = " + cache, path lookup";

struct Ladder {
    std::string mode;  // ladder_label: "path", "photons", "direct+photons", "final-gather + cache", ...
    std::vector<Rung> rungs;
    std::filesystem::path picture;  // test | reference | error of the best rung within the budget
};

struct QualityResult {
    std::string name;
    std::uint32_t size = 0, reference_spp = 0, max_bounces = 0;
    std::uint32_t photon_bounces = 0;  // of the .kdp the photon modes read
    int threads = 0;
    double seconds = 0;
    std::vector<double> budgets;
    double edge_share = 0;  // of the pixels, near geometric edges
    std::filesystem::path reference_file;
    bool reference_reused = false;
    double reference_render_seconds = 0;  // 0 when reused
    std::string reference_backend;        // "cpu" (every core) or "cuda" when rendered
    std::vector<Ladder> ladders;
};

QualityResult run_quality_bench(const QualityConfig& config);

// The image's mean over all pixels and channels, and over each horizontal third of its rows.
struct ImageMeans {
    double all = 0;
    std::array<double, 3> thirds{};
};
ImageMeans image_means(const Image& image);

}  // namespace kdpm::bench
