#pragma once
// Everything kdpm-view's command line decides, handed from main() to the viewer.
#include <cstdint>
#include <optional>
#include <string>

#include "runtime/backend/backend_kind.h"
#include "runtime/render/camera_override.h"
#include "runtime/render/render_settings.h"
#include "runtime/view/view_options.h"

namespace kdpm {

struct ViewerConfig {
    std::string geometry_path;
    std::string photon_path;  // empty: no photon map
    std::uint32_t width = 0, height = 0;  // 0: the file camera's
    CameraOverride camera;                // the start (and reset) view: the file's camera with these parts replaced
    std::uint32_t k = 0;                  // 0: the scene's default
    std::optional<RenderMode> mode;       // default: photons with a photon map, else direct
    BackendRequest backend = BackendRequest::automatic;
    std::uint32_t max_spp = 16;           // progressive refinement stops here
    std::uint32_t preview_divisor = 4;    // preview resolution = full / divisor per axis
    std::uint32_t light_samples = 16;
    ViewKind view = ViewKind::shaded;
    float exposure_stops = 0.0f;
    ToneMap tone_map = ToneMap::aces;
    bool quiet = false;
    // Scripted runs: `fly_frames` moving frames (previews), then `frames` full-resolution frames,
    // then the screenshot, then exit.
    int frames = 0;
    int fly_frames = 0;
    std::string screenshot;
    bool panel = false;  // scripted runs show the control panel, and screenshots include it
};

// Runs the window until Esc / close, or the scripted frames; returns the exit code.
int run_viewer(const ViewerConfig& config);

}  // namespace kdpm
