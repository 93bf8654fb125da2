#include "tools/cli/render_options.h"

#include "formats/camera_check.h"
#include "formats/scene_limits.h"

namespace kdpm::cli {

void add_render_options(Args& args, RenderOptions& o, const std::string& mode_default) {
    const int max_side = static_cast<int>(kMaxImageSide);
    args.option("width", &o.width, "N", "image width (default: the scene camera's)", 1, max_side)
        .option("height", &o.height, "N", "image height (default: the scene camera's)", 1, max_side)
        .option("k", &o.k, "N",
                "photons per radiance estimate, " + std::to_string(kMinEstimateK) + ".." + std::to_string(kMaxEstimateK) +
                    " (default: the scene card's)",
                static_cast<int>(kMinEstimateK), static_cast<int>(kMaxEstimateK))
        .option("mode", "MODE", render_mode_help(mode_default),
                [&o](const std::string& v) { o.mode = parse_render_mode(v); })
        .option("light-samples", &o.light_samples, "N",
                "shadow rays at each diffuse point, lights picked by power (default 16)", 1, 4096)
        .option("backend", "auto|cpu|cuda", "where kernels run (default auto: CUDA when a device exists)",
                [&o](const std::string& v) { o.backend = parse_backend_request(v); })
        .option("exposure", &o.exposure, "STOPS", "exposure in stops (default 0)", -double(kMaxExposureStops),
                double(kMaxExposureStops))
        .option("tonemap", "aces|reinhard|none", "tone mapping for 8-bit outputs and the window (default aces)",
                [&o](const std::string& v) { o.tone_map = parse_tone_map(v); })
        .option("threads", &o.threads, "N", "CPU worker threads, 0 = all cores (default 0)", 0, 4096)
        .flag("quiet", &o.quiet, "print nothing but errors");
}

}  // namespace kdpm::cli
