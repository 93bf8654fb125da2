#pragma once
// Irradiance caching for final gathering (Ward, Rubinstein & Clear 1988; gradients after Ward &
// Heckbert 1992): gather rays are sent only at cache records, and every diffuse vertex reads the
// records' interpolated irradiance.
//
// Deterministic whatever the thread count, by a coarse-to-fine sequence of levels rather than a
// scan in pixel order (which would be sequential): at pixel strides 16, 8, 4, 2, 1, the level's
// pixels that no existing record covers each get a record, made in parallel (records depend only
// on their vertex), appended in pixel order; the tree is rebuilt with the neighbours' clamps; a
// last pass at stride 1 covers what the clamps of the finest level uncovered; then every vertex
// is interpolated in parallel. Which vertex gets a record depends only on the records of coarser
// levels, never on timing. Records persist over the frame's samples.
#include <cstdint>
#include <stdexcept>

#include "runtime/render/final_gather/final_gather_pass.h"
#include "runtime/render/final_gather/irradiance_record_tree.h"

namespace kdpm {

struct CpuDevice;
struct PinholeCamera;

// A record covers at least this share of the image's height around it, however near the
// geometry, so that the nearest-hit radii make no more records than Ward's harmonic means did
// (measured on the Sponza at 512x512: 1/64, 8 pixels, 14866 records where the harmonic means
// made 14378; 2 pixels 51297 records, twice the time and no less error). A share, not pixels:
// on a 32-pixel image 8 pixels would blur a quarter of it.
inline constexpr float kMinRecordReach = 1.0f / 64.0f;
inline constexpr float kMinRecordReachPixels = 2.0f;  // and at least this many pixels

struct IrradianceCache {
    IrradianceRecordTree tree;
    float min_radius = 0.0f, max_radius = 1e30f;  // scene-wide clamp of the records' R_i
    std::uint64_t points = 0;                     // diffuse vertices interpolated

    IrradianceCache(float accuracy, float min_r, float max_r) : tree(accuracy), min_radius(min_r), max_radius(max_r) {}
};

// One sample's gather pass with the cache: records where needed (sized by the camera's pixel
// footprint), then the interpolation. Runs on the CPU backend (the records and their tree live
// in host memory).
void run_cached_gather(CpuDevice& dev, IrradianceCache& cache, const FinalGatherPass& pass,
                       const PinholeCamera& camera);

// Other backends do not run the cache: the renderer turns it off for them (irradiance_cache
// in FramePlan), so this is never reached.
template <class Device>
void run_cached_gather(Device&, IrradianceCache&, const FinalGatherPass&, const PinholeCamera&) {
    throw std::logic_error("the irradiance cache runs on the CPU backend only");
}

}  // namespace kdpm
