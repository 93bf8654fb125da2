// kdpm-view scene.kdg [scene.kdp]: an interactive window onto the renderer (fly camera,
// progressive refinement, views, stats), or a scripted run that saves a screenshot.
#include <filesystem>
#include <string>
#include <vector>

#include "formats/output_file.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/render/default_mode.h"
#include "runtime/view/viewer_config.h"
#include "tools/cli/args.h"
#include "tools/cli/render_options.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;

namespace {

int run(int argc, char** argv) {
    ViewerConfig cfg;
    cli::RenderOptions common;
    int spp = 16, preview = 4;
    cli::Args args("kdpm-view", "Interactive viewer for a kdpm scene (geometry kd-tree + optional photon kd-tree).");
    args.positional("scene.kdg", &cfg.geometry_path, "geometry kd-tree from kdpm-build-geometry")
        .positional("scene.kdp", &cfg.photon_path, "photon kd-tree from kdpm-build-photons (optional)", false);
    cli::add_render_options(args, common, kDefaultModeText);
    args.option("view", "VIEW", "shaded (default), depth, normal or density (photon density; needs a .kdp)",
                [&](const std::string& v) { cfg.view = parse_view(v); })
        .option("spp", &spp, "N", "progressive refinement stops at N samples per pixel (default 16)", 1, 4096)
        .option("preview-divisor", &preview, "N", "moving-camera resolution is 1/N per axis (default 4)", 1, 64)
        .option("frames", &cfg.frames, "N", "scripted: render N full-resolution frames, then exit", 1, 100000)
        .option("fly", &cfg.fly_frames, "N", "scripted: first fly forward for N preview frames", 1, 100000)
        .option("screenshot", &cfg.screenshot, "FILE", "scripted: save the last frame as displayed (PNG, ...)")
        .flag("panel", &cfg.panel, "scripted: show the control panel; the screenshot is the window as shown");
    cli::add_camera_options(args, common.camera);
    args.parse(argc, argv);
    cfg.mode = common.mode;
    cfg.backend = common.backend;
    cfg.tone_map = common.tone_map;
    cfg.quiet = common.quiet;
    cfg.camera = common.camera;
    cfg.exposure_stops = static_cast<float>(common.exposure);
    cfg.width = static_cast<std::uint32_t>(common.width);
    cfg.height = static_cast<std::uint32_t>(common.height);
    cfg.k = static_cast<std::uint32_t>(common.k);
    cfg.max_spp = static_cast<std::uint32_t>(spp);
    cfg.preview_divisor = static_cast<std::uint32_t>(preview);
    cfg.light_samples = static_cast<std::uint32_t>(common.light_samples);
    // A screenshot that cannot be written is refused before any frame is rendered.
    if (!cfg.screenshot.empty()) {
        std::vector<std::filesystem::path> inputs{cfg.geometry_path};
        if (!cfg.photon_path.empty()) inputs.push_back(cfg.photon_path);
        check_output_destination(cfg.screenshot, inputs);
    }
    ThreadLimit limit(common.threads);
    return run_viewer(cfg);
}

}  // namespace

int main(int argc, char** argv) {
    return cli::run_tool("kdpm-view", [&] { return run(argc, argv); });
}
