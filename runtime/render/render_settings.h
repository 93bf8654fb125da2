#pragma once
// What one frame should be: resolution, camera, sampling, the lighting method, AOVs and post.
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>

#include "formats/geometry_layout.h"
#include "runtime/render/final_gather/gather_lookup.h"
#include "runtime/render/image/image.h"
#include "runtime/render/image/post_process.h"
#include "runtime/render/render_modes.h"
#include "runtime/render/stage_times.h"

namespace kdpm {

// The most gather rays per diffuse point (mode final-gather): a ray's index shares a 32-bit
// random-number counter with its vertex.
inline constexpr std::uint32_t kMaxGatherRays = 65536;

struct RenderSettings {
    std::uint32_t width = 0, height = 0;  // 0: the camera record's
    std::uint32_t spp = 1;
    // A frame may be one part of a longer run of samples (kdpm-view's refinement resumes where
    // its last frame stopped): it takes samples first_sample .. first_sample + spp - 1 of a run of
    // sequence_spp (0: first_sample + spp). The camera jitters whenever the run has more than one
    // sample, so the parts' averages, weighted by their spp, average to the whole run's image.
    std::uint32_t first_sample = 0;
    std::uint32_t sequence_spp = 0;
    RenderMode mode = RenderMode::photons;
    std::uint32_t k = 0;                  // photons per estimate; 0: the scene's default (else 100)
    float max_radius = -1.0f;             // photon search limit; < 0: automatic, 0: unlimited
    bool cone_filter = false;             // weight photons by a cone filter (sharper caustics)
    float disc_flatten = 0.0f;            // flatten the photon search toward the surface (0: a sphere)
    bool fixed_radius = false;            // every photon within the search limit instead of the k nearest
    std::uint32_t light_samples = 16;     // shadow rays per diffuse point (lights picked by power)
    std::uint32_t max_depth = 8;          // mirror/glass bounces followed
    std::uint32_t max_bounces = 0;        // modes path, sppm: diffuse vertices per path; 0: unlimited (roulette)
    std::uint32_t passes = 16;            // mode sppm: progressive passes (the camera is jittered anew in each)
    std::uint64_t photons_per_pass = 0;   // mode sppm: photon paths shot per pass; 0: one per pixel
    float sppm_radius = 0.0f;             // mode sppm: initial gather radius; 0: from the scene
    std::uint32_t gather_rays = 64;       // mode final-gather: gather rays per diffuse point and sample
    GatherLookup gather_lookup = GatherLookup::irradiance_map;  // mode final-gather: what a gather hit reads
    bool irradiance_cache = true;         // mode final-gather: gather only at cache records (CPU backend)
    float ic_accuracy = 0.2f;             // the cache's error bound a: records are used where e_i < a
    // Keep the cache's records for this renderer's later frames while the scene's gather settings
    // stay the same (the viewer): records hold irradiance, which does not depend on the view.
    bool keep_irradiance_cache = false;
    std::optional<CameraRecord> camera;   // overrides the file's camera (viewer, benchmarks)
    AovSet aovs;
    PostSettings post;
    std::function<void(double)> progress;  // called on the host with the fraction done
};

struct RenderResult {
    Image linear;   // radiance, before exposure
    Image exposed;  // exposure and bloom applied (what EXR files get)
    Image display;  // tone-mapped sRGB in [0, 1] (what PNG files get)
    PostSettings post;  // what exposed and display were made with
    AovImages aovs;
    StageTimes times;
};

}  // namespace kdpm
