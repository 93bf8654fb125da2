#include "tools/bench/quality_bench.h"

#include <algorithm>
#include <cctype>
#include <thread>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/scene_card.h"
#include "builders/photons/photon_map_writer.h"
#include "runtime/backend/thread_limit.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/render/image/image_output.h"
#include "runtime/render/image/image_stats.h"
#include "runtime/render/renderer.h"
#include "runtime/render/scene_loader.h"
#include "runtime/render/stage_times.h"
#include "tools/bench/reference_cache.h"
#include "tools/cli/progress.h"
#include "tools/photons/irradiance_step.h"

namespace kdpm::bench {
namespace {

// The scene's .kdg and .kdp as the toolchain's defaults make them (the .kdp with the irradiance
// map final gathering reads); builds are deterministic, so a rebuild gives the same bytes.
// "Unlimited" photon bounces, as sppm's: Russian roulette ends nearly every path long before.
constexpr std::uint32_t kUnlimitedPhotonBounces = 63;

std::uint32_t photon_bounces_of(const QualityConfig& c, const Scene& scene) {
    if (c.photon_bounces < 0) return scene.bounces;
    return c.photon_bounces == 0 ? kUnlimitedPhotonBounces : static_cast<std::uint32_t>(c.photon_bounces);
}

std::uint32_t build_scene_files(const QualityConfig& c, const std::filesystem::path& kdg, const std::filesystem::path& kdp) {
    if (c.say) c.say("building the .kdg and .kdp");
    const Scene scene = load_scene_input(c.card);
    build_geometry_file(scene, KdBuildParams{}).writer.write(kdg);
    const GeometryFile geometry = GeometryFile::open(kdg);
    ShootOptions shoot;
    shoot.photons = c.photons ? c.photons : scene.photons;
    shoot.max_bounces = photon_bounces_of(c, scene);
    ShotPhotons shot = shoot_photons(geometry.view(), shoot);
    PhotonHitSet set{shot.info, std::move(shot.hits)};
    build_photon_map_file(set, PhotonTreeOptions{}, {}, default_photon_irradiance()).writer.write(kdp);
    return shoot.max_bounces;
}

struct RungSettings {
    std::string label;
    RenderSettings settings;
};

// A ladder: rung i's settings, or nothing past the last sensible rung.
using LadderStep = std::function<std::optional<RungSettings>(int)>;

struct LadderPlan {
    std::string mode;
    LadderStep step;
    double stop_seconds;  // the ladder ends after the first rung that took longer
};

std::string plural(std::uint32_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::vector<LadderPlan> ladder_plans(const QualityConfig& c) {
    // One rung past the largest budget shows where the curve goes.
    double stop = 2.0 * c.seconds;
    for (double b : c.budgets) stop = std::max(stop, b);
    const std::uint32_t size = c.size, max_bounces = c.max_bounces;
    auto base = [size](RenderMode mode) {
        RenderSettings s;
        s.width = s.height = size;
        s.mode = mode;
        return s;
    };
    auto by_spp = [base, max_bounces](RenderMode mode) {
        return [base, max_bounces, mode](int i) -> std::optional<RungSettings> {
            if (i > 16) return std::nullopt;
            RenderSettings s = base(mode);
            s.spp = 1u << i;
            if (mode == RenderMode::path) s.max_bounces = max_bounces;
            return RungSettings{plural(s.spp, "spp", "spp"), s};
        };
    };
    // Final gathering: samples per pixel and gather rays doubled in turn (rays up to 1024): at one
    // sample the image is sampled at pixel centres, and the edges' aliasing, not the gather
    // noise, bounds its error however many rays are sent.
    auto by_gather_rays = [base](std::uint32_t first, bool cache, GatherLookup lookup = GatherLookup::irradiance_map) {
        return [base, first, cache, lookup](int i) -> std::optional<RungSettings> {
            RenderSettings s = base(RenderMode::final_gather);
            s.irradiance_cache = cache;
            s.gather_lookup = lookup;
            std::uint32_t rays = first, spp = 1;
            for (int j = 0; j < i; ++j) (j % 2 == 0 || rays >= 1024 ? spp : rays) *= 2;
            if (spp > 1024) return std::nullopt;
            s.gather_rays = rays;
            s.spp = spp;
            return RungSettings{plural(rays, "gather ray", "gather rays") + ", " + plural(spp, "spp", "spp"), s};
        };
    };
    auto by_passes = [base, max_bounces](int i) -> std::optional<RungSettings> {
        if (i > 16) return std::nullopt;
        RenderSettings s = base(RenderMode::sppm);
        s.passes = 1u << i;
        s.max_bounces = max_bounces;
        return RungSettings{plural(s.passes, "pass", "passes"), s};
    };
    std::vector<LadderPlan> plans{
        {ladder_label(RenderMode::path), by_spp(RenderMode::path), stop},
        {ladder_label(RenderMode::photons), by_spp(RenderMode::photons), stop},
        {ladder_label(RenderMode::direct_photons), by_spp(RenderMode::direct_photons), stop},
        {ladder_label(RenderMode::final_gather, kCachedGather), by_gather_rays(16, true), stop},
        {ladder_label(RenderMode::final_gather, kUncachedGather), by_gather_rays(4, false), stop},
        {ladder_label(RenderMode::sppm), by_passes, std::max(stop, c.sppm_seconds)},
    };
    if (c.breakdown) {
        plans.push_back({ladder_label(RenderMode::final_gather, kEstimateLookup),
                         by_gather_rays(16, true, GatherLookup::estimate), stop});
        plans.push_back({ladder_label(RenderMode::final_gather, kPathLookup), by_gather_rays(16, true, GatherLookup::path),
                         stop});
    }
    return plans;
}

// The normal and depth AOVs of the centre rays, for edge_mask.
std::vector<std::uint8_t> scene_edges(Renderer& renderer, std::uint32_t size) {
    RenderSettings s;
    s.width = s.height = size;
    s.mode = RenderMode::albedo;
    s.aovs.depth = s.aovs.normal = true;
    const RenderResult r = renderer.render(s);
    return edge_mask(r.aovs, static_cast<int>(size), static_cast<int>(size));
}

// The file name of a ladder's picture: its label with every non-alphanumeric run as one '-'.
std::string picture_name(const std::string& scene, const std::string& mode) {
    std::string out = scene + "-";
    for (char ch : mode) {
        if (std::isalnum(static_cast<unsigned char>(ch))) out += ch;
        else if (out.back() != '-') out += '-';
    }
    while (out.back() == '-') out.pop_back();
    return out + ".png";
}

Rung measure(const RungSettings& r, Renderer& renderer, const Image& reference, const ImageMeans& ref_means,
             const std::vector<std::uint8_t>& edges, Image& image) {
    Rung rung;
    rung.setting = r.label;
    StopWatch watch;
    RenderResult result = renderer.render(r.settings);
    rung.seconds = watch.lap_ms() / 1000.0;
    rung.regions = split_error(result.linear, reference, edges);
    rung.relmse = relative_mse(result.linear, reference);
    const ImageMeans means = image_means(result.linear);
    rung.mean_ratio = ref_means.all > 0 ? means.all / ref_means.all : 0.0;
    for (int t = 0; t < 3; ++t) rung.third_ratio[t] = ref_means.thirds[t] > 0 ? means.thirds[t] / ref_means.thirds[t] : 0.0;
    image = std::move(result.linear);
    return rung;
}

}  // namespace

ImageMeans image_means(const Image& image) {
    ImageMeans m;
    m.all = mean_of(image);
    const std::size_t row = static_cast<std::size_t>(image.width) * 3;
    for (int t = 0; t < 3; ++t) {
        const std::size_t begin = row * static_cast<std::size_t>(image.height * t / 3);
        const std::size_t end = row * static_cast<std::size_t>(image.height * (t + 1) / 3);
        m.thirds[t] = end > begin ? mean_of(image.rgb, begin, end) : 0.0;
    }
    return m;
}

QualityResult run_quality_bench(const QualityConfig& c) {
    QualityResult out;
    out.name = c.name;
    out.size = c.size;
    out.reference_spp = c.reference_spp;
    out.max_bounces = c.max_bounces;
    out.threads = c.threads;
    out.seconds = c.seconds;
    out.budgets = c.budgets;
    const auto kdg = c.work_dir / (c.name + ".kdg");
    const auto kdp = c.work_dir / (c.name + ".kdp");
    out.photon_bounces = build_scene_files(c, kdg, kdp);
    const LoadedScene loaded = LoadedScene::load(kdg, kdp);

    ReferenceKey key;
    key.scene = c.name;
    key.geometry = kdg;
    key.width = key.height = c.size;
    key.spp = c.reference_spp;
    key.max_bounces = c.max_bounces;
    key.max_depth = RenderSettings{}.max_depth;
    out.reference_file = c.work_dir / reference_file_name(key);
    Image reference;
    if (std::optional<Image> cached = load_reference(out.reference_file, key)) {
        if (c.say) c.say("reusing the reference " + out.reference_file.string());
        reference = std::move(*cached);
        out.reference_reused = true;
    } else {
        const BackendSelection backend = select_backend(c.reference_backend);
        if (c.say && !backend.notice.empty()) c.say(backend.notice);
        out.reference_backend = backend_name(backend.kind);
        if (c.say) c.say("rendering the reference (" + std::to_string(c.reference_spp) + " spp, " + out.reference_backend + ")");
        RenderSettings s;
        s.width = s.height = c.size;
        s.mode = RenderMode::path;
        s.spp = c.reference_spp;
        s.max_bounces = c.max_bounces;
        s.max_depth = key.max_depth;
        cli::Progress bar("reference " + c.name, !c.progress_bar);
        s.progress = [&](double f) { bar.update(f); };
        Renderer renderer(loaded.views(), backend.kind);
        StopWatch watch;
        reference = renderer.render(s).linear;
        out.reference_render_seconds = watch.lap_ms() / 1000.0;
        bar.finish();
        store_reference(out.reference_file, reference);
    }
    const ImageMeans ref_means = image_means(reference);

    ThreadLimit limit(c.threads);
    Renderer renderer(loaded.views(), BackendKind::cpu);
    renderer.render(ladder_plans(c).front().step(0)->settings);  // warm-up: first-touch costs
    const std::vector<std::uint8_t> edges = scene_edges(renderer, c.size);
    for (std::uint8_t e : edges) out.edge_share += e;
    out.edge_share /= static_cast<double>(edges.empty() ? 1 : edges.size());
    if (!c.images_dir.empty()) std::filesystem::create_directories(c.images_dir);
    for (const LadderPlan& plan : ladder_plans(c)) {
        Ladder ladder;
        ladder.mode = plan.mode;
        Image image, best;
        double best_relmse = 0;
        for (int i = 0; i < c.max_rungs; ++i) {
            const std::optional<RungSettings> settings = plan.step(i);
            if (!settings) break;
            const Rung rung = measure(*settings, renderer, reference, ref_means, edges, image);
            if (rung.seconds <= c.seconds && (best.rgb.empty() || rung.relmse < best_relmse)) {
                best_relmse = rung.relmse;
                std::swap(best, image);
            }
            if (c.say)
                c.say(plan.mode + ", " + rung.setting + ": " + std::to_string(rung.seconds) + " s, relMSE " +
                      std::to_string(rung.relmse));
            ladder.rungs.push_back(rung);
            if (rung.seconds > plan.stop_seconds) break;
        }
        if (!c.images_dir.empty() && !best.rgb.empty()) {
            ladder.picture = c.images_dir / picture_name(c.name, plan.mode);
            const Image picture = side_by_side(best, reference);
            write_frame(ladder.picture, FrameOutput{&picture, &picture, nullptr, AovSet{}});
        }
        out.ladders.push_back(std::move(ladder));
    }
    return out;
}

}  // namespace kdpm::bench
