#pragma once
// kdpm-bench's "full frame per mode" table: the median time of a whole frame (trace, gather and
// shade, post-processing included) in each lighting mode, and the interactive viewer's frame
// rate in the report's case (photons, k = 32, one sample per pixel), measured as kdpm-view makes
// a frame without its window.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "runtime/render/scene_views.h"

namespace kdpm::bench {

struct ModeFrameRow {
    std::string mode;      // "photons", "final-gather", ...
    std::string settings;  // "k=32", "64 gather rays, cache on", ...
    double frame_ms = 0;   // median of whole frames
    double cuda_frame_ms = 0;  // the same on CUDA; 0 when not measured
    int units = 1;         // sppm: passes in the frame (frame_ms / units is the time per pass)
};

struct ModeFrames {
    std::uint32_t width = 0, height = 0;
    int threads = 0;  // all threads
    std::vector<ModeFrameRow> rows;
    int viewer_threads = 0;      // two, or fewer on a smaller machine
    double viewer_frame_ms = 0;  // median: render + compose + 8-bit conversion
    double viewer_cuda_frame_ms = 0;  // the same frame rendered on CUDA; 0 when not measured
    // kdpm-view's refinement once the camera stops, to kRefinementCap samples per pixel: each step
    // resumed where the last stopped and folded in (as kdpm-view does), and each step a fresh
    // render (as before); one of each, alternating, best of two.
    double refinement_resumed_ms = 0, refinement_fresh_ms = 0;
    std::string cuda_note;            // why the CUDA column stopped short; empty when it did not
};

inline constexpr std::uint32_t kRefinementCap = 8;

struct ModeFrameConfig {
    std::uint32_t width = 512, height = 512;
    int frames = 3;           // frames per median (after one warm-up frame)
    int threads = 1;          // all threads
    std::uint32_t gather_rays = 64;
    std::uint32_t sppm_passes = 4;
    bool cuda = false;        // also on the CUDA backend (a device was started)
    std::function<void(const std::string&)> say;  // progress lines
};

// Photon modes are left out when the scene has no photon maps.
ModeFrames measure_mode_frames(const SceneViews& scene, const ModeFrameConfig& config);

// The table (with CUDA columns where any CUDA frame was measured) and the viewer's frame rate
// against its target (>= 8 frames per second on two cores, Sponza 512x512); empty when nothing
// was measured.
std::string format_mode_frames(const std::string& scene, const ModeFrames& frames, bool markdown);

}  // namespace kdpm::bench
