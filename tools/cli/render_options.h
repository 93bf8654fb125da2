#pragma once
// The options kdpm-render and kdpm-view share, declared once so that their names, ranges and
// help cannot drift apart: image size, k, mode, shadow rays, backend, exposure, tone map,
// threads, quiet and the camera.
#include <optional>
#include <string>

#include "runtime/backend/backend_kind.h"
#include "runtime/render/camera_override.h"
#include "runtime/render/image/post_process.h"
#include "runtime/render/render_modes.h"
#include "tools/cli/args.h"
#include "tools/cli/camera_override.h"

namespace kdpm::cli {

struct RenderOptions {
    int width = 0, height = 0;  // 0: the camera's
    int k = 0;                  // 0: the scene card's
    int light_samples = 16;
    int threads = 0;            // 0: all cores
    double exposure = 0.0;      // stops
    std::optional<RenderMode> mode;  // none given: the tool's default
    BackendRequest backend = BackendRequest::automatic;
    ToneMap tone_map = ToneMap::aces;
    bool quiet = false;
    CameraOverride camera;
};

// mode_default: the tool's sentence on the mode it renders when --mode is not given. The camera
// options open a group of their own in --help: add them last (add_camera_options, options.camera).
void add_render_options(Args& args, RenderOptions& options, const std::string& mode_default);

}  // namespace kdpm::cli
