// kdpm-render scene.kdg [scene.kdp] -o out.png|out.exr: renders one frame of a scene with
// photon mapping on the CPU or a CUDA GPU and prints the per-stage timing table.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "formats/output_file.h"
#include "formats/scene_limits.h"
#include "runtime/backend/backend_kind.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/render/default_mode.h"
#include "runtime/render/image/image_output.h"
#include "runtime/render/renderer.h"
#include "runtime/render/scene_loader.h"
#include "tools/cli/args.h"
#include "tools/cli/progress.h"
#include "tools/cli/render_options.h"
#include "tools/cli/run_tool.h"

using namespace kdpm;

namespace {

AovSet parse_aovs(const std::string& text) {
    AovSet set;
    std::stringstream list(text);
    std::string item;
    while (std::getline(list, item, ',')) {
        if (item == "depth") set.depth = true;
        else if (item == "normal") set.normal = true;
        else if (item == "position") set.position = true;
        else if (item == "triangle") set.triangle = true;
        else if (!item.empty())
            throw std::invalid_argument("unknown AOV '" + item + "' (expected depth, normal, position, triangle)");
    }
    return set;
}

// --ic-accuracy: a number in (0, 1].
float parse_ic_accuracy(const std::string& text) {
    float a = 0.0f;
    try {
        a = static_cast<float>(cli::parse_finite(text));
    } catch (const std::invalid_argument&) {
        a = 0.0f;  // refused below
    }
    if (!(a > 0.0f && a <= 1.0f))
        throw std::invalid_argument("expected a number in (0, 1], got '" + text + "'");
    return a;
}

int run(int argc, char** argv) {
    std::string geometry_path, photon_path, output;
    RenderSettings settings;
    cli::RenderOptions common;
    int spp = 1, max_depth = 8, max_bounces = 0;
    int passes = 0, photons_per_pass = 0;  // 0: not given
    int gather_rays = 64;
    double max_radius = -1.0, disc = 0.0, sppm_radius = 0.0;

    cli::Args args("kdpm-render", "Render a frame of a kdpm scene (geometry kd-tree + photon kd-tree) to an image.");
    args.positional("scene.kdg", &geometry_path, "geometry kd-tree from kdpm-build-geometry")
        .positional("scene.kdp", &photon_path, "photon kd-tree from kdpm-build-photons (not needed for --mode direct)",
                    false)
        .option("output", &output, "FILE", "output image, format by extension (.png, .exr, ...)");
    cli::add_render_options(args, common, kDefaultModeText);
    args.option("spp", &spp, "N", "camera samples per pixel (default 1: pixel centres)", 1, 4096)
        .option("max-radius", &max_radius, "R",
                "photon search limit (default: automatic, 4x the photon map's typical k-radius; 0: none)", 0.0, 1e30)
        .option("filter", "box|cone", "photon weights in the estimate: box (default: all equal) or cone (nearer count more)",
                [&](const std::string& v) {
                    if (v != "box" && v != "cone") throw std::invalid_argument("expected box or cone, got '" + v + "'");
                    settings.cone_filter = v == "cone";
                })
        .option("gather", "knn|radius",
                "photons per estimate: the k nearest (default), or every photon within --max-radius (default: the "
                "typical radius of k photons)",
                [&](const std::string& v) {
                    if (v != "knn" && v != "radius") throw std::invalid_argument("expected knn or radius, got '" + v + "'");
                    settings.fixed_radius = v == "radius";
                })
        .option("disc", &disc, "F",
                "flatten the photon search toward the surface against leaks (0: a sphere, the default; F: the "
                "axis along the normal is 1/sqrt(1+F) as long)", 0.0, 1e6)
        .option("max-depth", &max_depth, "N", "mirror/glass bounces followed (default 8)", 1, 64)
        .option("max-bounces", &max_bounces, "N",
                "modes path and sppm: diffuse bounces shaded per path, 1 = direct light only (default 0: unlimited, "
                "ended by Russian roulette)", 0, 1000000)
        .option("passes", &passes, "N", "mode sppm: progressive passes (default 16)", 1, 1000000)
        .option("photons-per-pass", &photons_per_pass, "N", "mode sppm: photon paths shot per pass (default: one per pixel)",
                1, 2147483647)
        .option("sppm-radius", &sppm_radius, "R",
                "mode sppm: initial gather radius (default: the photon map's typical radius, else 1/100 of the "
                "scene's diagonal)", 1e-30, 1e30)
        .option("gather-rays", &gather_rays, "N",
                "mode final-gather: cosine-distributed gather rays per diffuse point and sample (default 64)", 1,
                static_cast<int>(kMaxGatherRays))
        .option("gather-lookup", "irradiance-map|estimate|path",
                "mode final-gather: what a gather ray reads where it hits a diffuse surface: the .kdp's precomputed "
                "irradiance (default), the photon map's k-nearest estimate there, or a path traced on (slow, no "
                "photon-map bias)",
                [&](const std::string& v) { settings.gather_lookup = parse_gather_lookup(v); })
        .option("irradiance-cache", "on|off",
                "mode final-gather: gather rays only at irradiance cache records, interpolated between them "
                "(default on; off: at every diffuse point; CPU backend only)",
                [&](const std::string& v) {
                    if (v != "on" && v != "off") throw std::invalid_argument("expected on or off, got '" + v + "'");
                    settings.irradiance_cache = v == "on";
                })
        .option("ic-accuracy", "A",
                "irradiance cache error bound a in (0, 1]: smaller makes more records (default 0.2)",
                [&](const std::string& v) { settings.ic_accuracy = parse_ic_accuracy(v); })
        .option("aov", "LIST", "also write depth,normal,position,triangle (EXR channels or out.NAME.exr files)",
                [&](const std::string& v) { settings.aovs = parse_aovs(v); })
        .flag("bloom", &settings.post.bloom, "add a glow around bright pixels");
    cli::add_camera_options(args, common.camera);
    args.short_name('o', "output");
    args.parse(argc, argv);
    settings.post.tone_map = common.tone_map;
    const bool quiet = common.quiet;
    if (output.empty()) throw std::runtime_error("no output file given (-o out.png)");
    // The default is never sppm: refused before any file is read.
    if (!(common.mode && *common.mode == RenderMode::sppm) && (passes || photons_per_pass || sppm_radius > 0.0))
        throw std::invalid_argument("--passes, --photons-per-pass and --sppm-radius are for --mode sppm");
    // Refuse an impossible destination (or one that is an input) before spending time on the frame.
    std::vector<std::filesystem::path> inputs{geometry_path};
    if (!photon_path.empty()) inputs.push_back(photon_path);
    check_output_destination(output, inputs);
    ThreadLimit limit(common.threads);

    BackendSelection selected = select_backend(common.backend);
    if (!selected.notice.empty() && !quiet) std::cerr << "kdpm-render: " << selected.notice << "\n";

    std::optional<std::filesystem::path> photons;
    if (!photon_path.empty()) photons = photon_path;
    LoadedScene scene = LoadedScene::load(geometry_path, photons);
    settings.mode = common.mode ? *common.mode : default_render_mode(scene.views());
    settings.camera = common.camera.applied_to(scene.views().camera);
    const GeometryInfo& bounds = scene.views().geometry.info;
    if (radius_too_small(max_radius, bounds.bounds_min, bounds.bounds_max))
        throw std::invalid_argument("--max-radius " + radius_limit_text(max_radius, bounds.bounds_min, bounds.bounds_max) +
                                    ": no photon would be found (0: no limit)");
    Renderer renderer(scene.views(), selected.kind);

    settings.width = static_cast<std::uint32_t>(common.width);
    settings.height = static_cast<std::uint32_t>(common.height);
    settings.spp = static_cast<std::uint32_t>(spp);
    settings.k = static_cast<std::uint32_t>(common.k);
    settings.max_radius = static_cast<float>(max_radius);
    settings.disc_flatten = static_cast<float>(disc);
    settings.light_samples = static_cast<std::uint32_t>(common.light_samples);
    settings.max_depth = static_cast<std::uint32_t>(max_depth);
    settings.max_bounces = static_cast<std::uint32_t>(max_bounces);
    if (passes) settings.passes = static_cast<std::uint32_t>(passes);
    settings.photons_per_pass = static_cast<std::uint64_t>(photons_per_pass);
    settings.sppm_radius = static_cast<float>(sppm_radius);
    settings.gather_rays = static_cast<std::uint32_t>(gather_rays);
    if (settings.mode == RenderMode::final_gather && !scene.views().photons.empty() &&
        !scene.views().photons.irradiance.present() && !quiet)
        std::cerr << "kdpm-render: " << photon_path
                  << " has no precomputed irradiance: gather hits use the k-nearest estimate (slower; rebuild it "
                     "with kdpm-build-photons)\n";
    if (settings.mode == RenderMode::final_gather && settings.irradiance_cache && selected.kind != BackendKind::cpu &&
        !quiet)
        std::cerr << "kdpm-render: the irradiance cache runs on the CPU backend only; on CUDA every diffuse point "
                     "sends gather rays\n";
    settings.post.exposure_stops = static_cast<float>(common.exposure);
    cli::Progress progress("rendering", quiet);
    settings.progress = [&](double f) { progress.update(f); };

    RenderResult result = renderer.render(settings);
    progress.finish();

    FrameOutput frame{&result.exposed, &result.display, &result.aovs, settings.aovs};
    auto written = write_frame(output, frame);

    if (!quiet) {
        std::cout << "kdpm-render: " << result.linear.width << "x" << result.linear.height << ", "
                  << (settings.mode == RenderMode::sppm ? settings.passes : settings.spp)
                  << (settings.mode == RenderMode::sppm ? " passes" : " spp") << ", mode " << render_mode_name(settings.mode) << ", backend " << backend_name(selected.kind)
                  << "\n";
        if (renderer.upload_ms() > 0)
            std::printf("  device start %.2f ms, scene upload %.2f ms\n", renderer.device_start_ms(), renderer.upload_ms());
        std::cout << format_stage_table(result.times, scene.load_ms());
        for (const auto& p : written) std::cout << "  wrote " << p.string() << "\n";
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return cli::run_tool("kdpm-render", [&] { return run(argc, argv); });
}
