#include "runtime/render/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "formats/scene_limits.h"
#include "runtime/render/frame_backend.h"
#include "runtime/render/frame_memory.h"
#include "runtime/render/image/image_pool.h"
#include "runtime/render/image/post_process.h"
#include "runtime/render/image_size.h"
#include "runtime/shading/ray_offset.h"

namespace kdpm {

// The irradiance cache kept between frames, with what its records depend on: the settings of the
// gather rays and of the photon estimates they read (not the camera: irradiance is view-independent).
struct KeptIrradianceCache {
    struct Key {
        std::uint32_t k, max_depth, gather_rays;
        float max_radius, disc_flatten, ic_accuracy, min_radius, max_record_radius;
        bool cone_filter, fixed_radius;
        GatherLookup lookup;
        bool operator==(const Key&) const = default;
    };
    // Past this many records the cache starts afresh: a long flight through a large scene would
    // otherwise grow it without bound (about 100 bytes a record).
    static constexpr std::size_t kMaxRecords = std::size_t(1) << 21;

    Key key;
    IrradianceCache cache;

    static Key key_of(const FramePlan& plan) {
        const RenderSettings& s = plan.settings;
        return {s.k, s.max_depth, s.gather_rays, s.max_radius, s.disc_flatten, s.ic_accuracy,
                plan.cache_min_radius, plan.cache_max_radius, s.cone_filter, s.fixed_radius, s.gather_lookup};
    }
    KeptIrradianceCache(const FramePlan& plan)
        : key(key_of(plan)), cache(plan.settings.ic_accuracy, plan.cache_min_radius, plan.cache_max_radius) {}
};

namespace {

// Photons up to 63 bounces stand for "unlimited" (roulette ends nearly every path before).
constexpr std::uint32_t kSppmUnlimitedPhotonBounces = 63;

SppmPlan sppm_plan(const RenderSettings& settings, const SceneViews& scene, std::uint32_t width, std::uint32_t height) {
    if (settings.passes < 1 || settings.passes > 1000000)
        throw std::runtime_error("sppm passes must be in 1..1000000, got " + std::to_string(settings.passes));
    SppmPlan sppm;
    sppm.passes = settings.passes;
    sppm.photons_per_pass = settings.photons_per_pass ? settings.photons_per_pass
                                                      : static_cast<std::uint64_t>(width) * height;
    if (sppm.photons_per_pass > 0xffffffffull)
        throw std::runtime_error("sppm photons per pass must be at most 4294967295");
    // A pass keeps its photons' hits and their grid on the host (about 4 stored per path in a
    // closed room) beside one shooting batch.
    const double photon_bytes = static_cast<double>(sppm.photons_per_pass) * 4.0 * (sizeof(PhotonHit) + sizeof(SppmPhoton)) +
                                static_cast<double>(64u << 20);
    const double available = static_cast<double>(available_memory_bytes());
    if (photon_bytes > available) {
        char text[200];
        std::snprintf(text, sizeof text,
                      "%llu sppm photons per pass need about %.1f GiB of memory, but only %.1f GiB is available; "
                      "shoot fewer (--photons-per-pass)",
                      static_cast<unsigned long long>(sppm.photons_per_pass), photon_bytes / 1073741824.0,
                      available / 1073741824.0);
        throw std::runtime_error(text);
    }
    const GeometryInfo& g = scene.geometry.info;
    const auto diagonal = static_cast<float>(bounds_diagonal(g.bounds_min, g.bounds_max));
    // The photon map's typical k-nearest radius when there is one, else 1/100 of the scene.
    sppm.initial_radius = settings.sppm_radius > 0.0f         ? settings.sppm_radius
                          : scene.photons.typical_radius > 0.0f ? scene.photons.typical_radius
                                                                : 0.01f * diagonal;
    if (!(sppm.initial_radius > 0.0f) || !std::isfinite(sppm.initial_radius))
        throw std::runtime_error("sppm needs a positive initial radius (--sppm-radius R)");
    sppm.photon_ray_offset = photon_ray_offset(g);
    sppm.max_photon_bounce = settings.max_bounces == 0 ? kSppmUnlimitedPhotonBounces
                                                       : std::min(settings.max_bounces - 1, 255u);
    return sppm;
}

}  // namespace

Renderer::Renderer(const SceneViews& scene, BackendKind backend)
    : scene_(scene), backend_(backend), images_(std::make_unique<ImagePool>()) {
    if (backend == BackendKind::cuda) {
#if defined(KDPM_HAVE_CUDA)
        impl_ = make_cuda_frame_backend(scene_);
#else
        throw std::runtime_error("this build of kdpm has no CUDA backend");
#endif
    } else {
        impl_ = make_cpu_frame_backend(scene_);
    }
}

Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

double Renderer::device_start_ms() const { return impl_->device_start_ms(); }
double Renderer::upload_ms() const { return impl_->upload_ms(); }

void Renderer::recycle(RenderResult&& frame) {
    images_->give(std::move(frame.linear));
    images_->give(std::move(frame.exposed));
    images_->give(std::move(frame.display));
}

std::vector<float> Renderer::photon_density(const std::vector<float>& positions, const std::vector<float>& normals,
                                            std::uint32_t k) {
    return impl_->photon_density(positions, normals, k);
}

RenderResult Renderer::render(const RenderSettings& settings) {
    FramePlan plan;
    plan.settings = settings;
    const CameraRecord camera = settings.camera ? *settings.camera : scene_.camera;
    const ImageSize size = image_size(settings.width, settings.height, camera);
    plan.width = size.width;
    plan.height = size.height;
    if (!(camera.vfov_degrees > 0.0f && camera.vfov_degrees < 180.0f))
        throw std::runtime_error("camera field of view must be in (0, 180) degrees");
    const bool progressive = settings.mode == RenderMode::sppm;
    const bool final_gather = settings.mode == RenderMode::final_gather;
    const std::uint32_t spp = std::max<std::uint32_t>(1, settings.spp);
    if (settings.first_sample > std::numeric_limits<std::uint32_t>::max() - spp)
        throw std::runtime_error("samples from " + std::to_string(settings.first_sample) + " on: too many for one run");
    const std::uint32_t sequence = settings.sequence_spp ? settings.sequence_spp : settings.first_sample + spp;
    if (settings.first_sample + spp > sequence)
        throw std::runtime_error("samples " + std::to_string(settings.first_sample) + ".." +
                                 std::to_string(settings.first_sample + spp - 1) + " are outside a run of " +
                                 std::to_string(sequence));
    if (progressive && settings.first_sample != 0)
        throw std::runtime_error("sppm renders whole runs of passes: no first sample can be given");
    plan.camera = PinholeCamera::from_record(camera, plan.width, plan.height, progressive ? settings.passes : sequence);
    plan.epsilon = render_ray_offset(scene_.geometry.info);
    if (final_gather && (settings.gather_rays < 1 || settings.gather_rays > kMaxGatherRays))
        throw std::runtime_error("gather rays must be in 1.." + std::to_string(kMaxGatherRays));
    if (final_gather && settings.irradiance_cache && !(settings.ic_accuracy > 0.0f && settings.ic_accuracy <= 1.0f))
        throw std::runtime_error("irradiance cache accuracy must be in (0, 1]");
    // The cache's records live on the host: the CUDA backend gathers at every vertex.
    plan.irradiance_cache = final_gather && settings.irradiance_cache && backend_ == BackendKind::cpu;
    {
        const auto& info = scene_.geometry.info;
        const auto diagonal = static_cast<float>(bounds_diagonal(info.bounds_min, info.bounds_max));
        plan.cache_min_radius = diagonal > 0.0f ? 1e-3f * diagonal : 1e-6f;
        plan.cache_max_radius = diagonal > 0.0f ? 0.5f * diagonal : 1e30f;
    }
    if (plan.gather_photons() && scene_.photons.empty())
        throw std::runtime_error(std::string("mode ") + render_mode_name(settings.mode) +
                                 " needs a photon map (.kdp); use --mode direct without one");
    // Memory the backend keeps from the last frame is this frame's to use again.
    check_frame_memory(plan.width, plan.height,
                       frame_memory_bytes(plan.width, plan.height, plan.gather_photons(), settings.aovs),
                       available_memory_bytes() + impl_->kept_bytes());
    if (plan.settings.k == 0) plan.settings.k = scene_.geometry.info.default_k ? scene_.geometry.info.default_k : 100;
    if (plan.gather_photons() && settings.fixed_radius &&
        !(settings.max_radius > 0.0f || (settings.max_radius < 0.0f && scene_.photons.typical_radius > 0.0f)))
        throw std::runtime_error(
            "a fixed-radius gather needs a radius: the photon map records none, give one (--max-radius R > 0)");

    if (progressive) plan.sppm = sppm_plan(settings, scene_, plan.width, plan.height);

    if (plan.irradiance_cache && settings.keep_irradiance_cache) {
        if (!kept_cache_ || !(kept_cache_->key == KeptIrradianceCache::key_of(plan)) ||
            kept_cache_->cache.tree.records().size() > KeptIrradianceCache::kMaxRecords)
            kept_cache_ = std::make_unique<KeptIrradianceCache>(plan);
        plan.kept_cache = &kept_cache_->cache;
    }

    RenderResult result;
    const int width = static_cast<int>(plan.width), height = static_cast<int>(plan.height);
    result.linear = images_->take(width, height);
    impl_->run(plan, result.linear, result.aovs, result.times);
    StopWatch watch;
    result.exposed = images_->take(width, height);
    result.display = images_->take(width, height);
    post_process(result.linear, settings.post, result.exposed, result.display);
    result.post = settings.post;
    result.times.post_ms += watch.lap_ms();
    return result;
}

}  // namespace kdpm
