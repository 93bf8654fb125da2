// kdpm-view scene.kdg [scene.kdp]: an interactive window onto the renderer (fly camera,
// progressive refinement, views, stats), or a scripted run that saves a screenshot.
#include <filesystem>
#include <string>
#include <vector>

#include "formats/output_file.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/view/viewer_config.h"
#include "tools/cli/args.h"
#include "tools/cli/camera_override.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;

namespace {

int run(int argc, char** argv) {
    ViewerConfig cfg;
    double exposure = 0.0;
    int threads = 0;
    int width = 0, height = 0, k = 0, spp = 16, preview = 4, light_samples = 16;
    cli::Args args("kdpm-view", "Interactive viewer for a kdpm scene (geometry kd-tree + optional photon kd-tree).");
    args.positional("scene.kdg", &cfg.geometry_path, "geometry kd-tree from kdpm-build-geometry")
        .positional("scene.kdp", &cfg.photon_path, "photon kd-tree from kdpm-build-photons (optional)", false)
        .option("width", &width, "N", "image width (default: the scene camera's)", 1, 16384)
        .option("height", &height, "N", "image height (default: the scene camera's)", 1, 16384)
        .option("k", &k, "N", "photons per radiance estimate, 2..256 (default: the scene card's)", 2, 256)
        .option("mode", "MODE",
                "photons, direct+photons, direct, path, sppm or final-gather (default: photons with a .kdp, else direct)",
                [&](const std::string& v) { cfg.mode = parse_render_mode(v); })
        .option("backend", "auto|cpu|cuda", "where kernels run (default auto: CUDA when a device exists)",
                [&](const std::string& v) { cfg.backend = parse_backend_request(v); })
        .option("view", "VIEW", "shaded (default), depth, normal or density (photon density; needs a .kdp)",
                [&](const std::string& v) { cfg.view = parse_view(v); })
        .option("exposure", &exposure, "STOPS", "exposure in stops (default 0)", -16.0, 16.0)
        .option("tonemap", "aces|reinhard|none", "tone mapping (default aces)",
                [&](const std::string& v) { cfg.tone_map = parse_tone_map(v); })
        .option("spp", &spp, "N", "progressive refinement stops at N samples per pixel (default 16)", 1, 4096)
        .option("preview-divisor", &preview, "N", "moving-camera resolution is 1/N per axis (default 4)", 1, 64)
        .option("light-samples", &light_samples, "N", "shadow rays per light at each diffuse point (default 16)",
                1, 4096)
        .option("frames", &cfg.frames, "N", "scripted: render N full-resolution frames, then exit", 1, 100000)
        .option("fly", &cfg.fly_frames, "N", "scripted: first fly forward for N preview frames", 1, 100000)
        .option("screenshot", &cfg.screenshot, "FILE", "scripted: save the last frame as displayed (PNG, ...)")
        .flag("panel", &cfg.panel, "scripted: show the control panel; the screenshot is the window as shown")
        .option("threads", &threads, "N", "CPU worker threads, 0 = all cores (default 0)", 0, 4096)
        .flag("quiet", &cfg.quiet, "print nothing but errors");
    cli::add_camera_options(args, cfg.camera);
    args.parse(argc, argv);
    cfg.exposure_stops = static_cast<float>(exposure);
    cfg.width = static_cast<std::uint32_t>(width);
    cfg.height = static_cast<std::uint32_t>(height);
    cfg.k = static_cast<std::uint32_t>(k);
    cfg.max_spp = static_cast<std::uint32_t>(spp);
    cfg.preview_divisor = static_cast<std::uint32_t>(preview);
    cfg.light_samples = static_cast<std::uint32_t>(light_samples);
    // A screenshot that cannot be written is refused before any frame is rendered.
    if (!cfg.screenshot.empty()) {
        std::vector<std::filesystem::path> inputs{cfg.geometry_path};
        if (!cfg.photon_path.empty()) inputs.push_back(cfg.photon_path);
        check_output_destination(cfg.screenshot, inputs);
    }
    ThreadLimit limit(threads);
    return run_viewer(cfg);
}

}  // namespace

int main(int argc, char** argv) {
    return cli::run_tool("kdpm-view", [&] { return run(argc, argv); });
}
