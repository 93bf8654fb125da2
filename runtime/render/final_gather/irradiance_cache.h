#pragma once
// Irradiance caching for final gathering (Ward, Rubinstein & Clear 1988; gradients after Ward &
// Heckbert 1992): gather rays are sent only at cache records, and every diffuse vertex reads the
// records' interpolated irradiance.
//
// Deterministic whatever the thread count, by a coarse-to-fine sequence of levels rather than a
// scan in pixel order (which would be sequential): at pixel strides 16, 8, 4, 2, 1, the level's
// pixels that no existing record covers each get a record, made in parallel (records depend only
// on their vertex), appended in pixel order; the tree is rebuilt; then every vertex is
// interpolated in parallel. Which vertex gets a record depends only on the records of coarser
// levels, never on timing. Records persist over the frame's samples.
#include <cstdint>
#include <stdexcept>

#include "runtime/render/final_gather/final_gather_pass.h"
#include "runtime/render/final_gather/irradiance_record_tree.h"

namespace kdpm {

struct CpuDevice;

struct IrradianceCache {
    IrradianceRecordTree tree;
    float min_radius = 0.0f, max_radius = 1e30f;  // clamp of the records' R_i
    std::uint64_t points = 0;                     // diffuse vertices interpolated

    IrradianceCache(float accuracy, float min_r, float max_r) : tree(accuracy), min_radius(min_r), max_radius(max_r) {}
};

// One sample's gather pass with the cache: records where needed, then the interpolation. Runs on
// the CPU backend (the records and their tree live in host memory).
void run_cached_gather(CpuDevice& dev, IrradianceCache& cache, const FinalGatherPass& pass);

// Other backends do not run the cache: the renderer turns it off for them (irradiance_cache
// in FramePlan), so this is never reached.
template <class Device>
void run_cached_gather(Device&, IrradianceCache&, const FinalGatherPass&) {
    throw std::logic_error("the irradiance cache runs on the CPU backend only");
}

}  // namespace kdpm
