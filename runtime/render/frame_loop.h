#pragma once
// One frame, written once for both backends: run_frame picks the mode's frame function (one case
// per mode), each runs its passes per sample over the frame arrays, then the sums come back to
// the host. `Device` is a BackendDevice (device_concept.h).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/backend/device_concept.h"
#include "runtime/backend/items_on_host.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/render/aov_arrays.h"
#include "runtime/render/camera.h"
#include "runtime/render/final_gather/final_gather_pass.h"
#include "runtime/render/final_gather/irradiance_cache.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/image/sample_average.h"
#include "runtime/render/passes/albedo_pass.h"
#include "runtime/render/passes/packet_trace_pass.h"
#include "runtime/render/passes/path_pass.h"
#include "runtime/render/passes/photon_gather_pass.h"
#include "runtime/render/passes/photon_tile_gather_pass.h"
#include "runtime/render/passes/shade_pass.h"
#include "runtime/render/passes/trace_pass.h"
#include "runtime/render/render_settings.h"
#include "runtime/render/sppm/sppm_loop.h"
#include "runtime/render/stage_times.h"

namespace kdpm {

// Decided on the host from the settings and the scene, the same for both backends; what the
// mode implies comes from its row in render_modes.h.
struct FramePlan {
    PinholeCamera camera;
    std::uint32_t width = 0, height = 0;
    RenderSettings settings;
    float epsilon = 1e-4f;
    SppmPlan sppm;                  // --mode sppm
    bool irradiance_cache = false;  // final-gather: gather rays only at cache records (CPU backend)
    float cache_min_radius = 0.0f, cache_max_radius = 1e30f;  // clamp of the records' R_i (scene units)
    IrradianceCache* kept_cache = nullptr;  // records from earlier frames to use and extend; null: a new cache

    std::uint64_t pixels() const { return static_cast<std::uint64_t>(width) * height; }
    RenderMode mode() const { return settings.mode; }
    bool gather_photons() const { return mode_needs_photons(settings.mode); }
    bool direct_light() const { return mode_info(settings.mode).direct_light; }
    bool keeps_vertices() const { return mode_info(settings.mode).diffuse_vertices; }
};

// The samples of a frame: the frame arrays (vertex slots when the mode keeps them), then
// sample(fb, s, lap, report) for each sample s of the run, then the average and the AOVs to the
// host. lap() returns the milliseconds since the last lap; report(s, passes_done) of 3.
template <class Device, class Sample>
void run_samples(Device& dev, const FramePlan& plan, Image& linear, AovImages& aovs, StageTimes& times,
                 Sample&& sample) {
    const std::uint64_t pixels = plan.pixels();
    // Modes without a shade pass (path: its vertices stay in registers) need only the sums and AOVs.
    const std::uint64_t per_pixel = plan.keeps_vertices() ? pixels : 0;
    const std::uint64_t slots = per_pixel * kMaxDiffuseVertices;
    const AovSet& want = plan.settings.aovs;
    StopWatch watch;

    // Only the sums start at zero; the trace pass writes every pixel's emitted light, vertex
    // count and AOVs, and the later passes read only the vertex slots it filled.
    auto accum = dev.template array<glm::vec3>(pixels);
    auto emitted = dev.template scratch<glm::vec3>(per_pixel);
    auto vertex_count = dev.template scratch<std::uint32_t>(per_pixel);
    auto vertices = dev.template scratch<DiffuseVertex>(slots);
    auto gathered = dev.template scratch<glm::vec3>(plan.gather_photons() ? slots : 0);
    const AovArrays<Device> aov_arrays(dev, want, pixels);

    FrameBuffersView fb;
    fb.width = plan.width;
    fb.height = plan.height;
    fb.emitted = per_pixel ? emitted.data() : nullptr;
    fb.vertex_count = per_pixel ? vertex_count.data() : nullptr;
    fb.vertices = per_pixel ? vertices.data() : nullptr;
    fb.gathered = plan.gather_photons() ? gathered.data() : nullptr;
    fb.accum = accum.data();
    aov_arrays.name_in(fb);
    times.transfer_ms += watch.lap_ms();

    const std::uint32_t spp = plan.settings.spp < 1 ? 1 : plan.settings.spp;
    // The samples first .. end - 1 of the run (Renderer::render checked that they fit).
    const std::uint32_t first = plan.settings.first_sample, end = first + spp;
    auto report = [&](std::uint32_t s, int passes_done) {
        if (plan.settings.progress) plan.settings.progress(((s - first) * 3.0 + passes_done) / (3.0 * spp));
    };
    auto lap = [&] { return watch.lap_ms(); };
    for (std::uint32_t s = first; s < end; ++s) sample(fb, s, lap, report);

    std::vector<glm::vec3> copied;  // only where the device's arrays are not host memory
    const glm::vec3* sums = items_on_host(dev, accum, copied);
    average_samples(sums, plan.width, plan.height, 1.0f / static_cast<float>(spp), linear);

    aov_arrays.to_host(dev, aovs);
    times.transfer_ms += watch.lap_ms();
}

// --mode path: one path pass per sample.
template <class Device>
void run_path_frame(Device& dev, const GeometryView& geometry, const LightSelection& lights, const FramePlan& plan,
                    Image& linear, AovImages& aovs, StageTimes& times) {
    run_samples(dev, plan, linear, aovs, times, [&](const FrameBuffersView& fb, std::uint32_t s, auto& lap, auto& report) {
        PathPass path{geometry, lights, plan.camera, fb, s, plan.settings.max_depth, plan.settings.max_bounces,
                      plan.epsilon};
        dev.launch(plan.pixels(), path);
        times.ray_tracing_ms += lap();
        report(s, 3);
    });
}

// The photon-map modes and direct light: per sample the trace pass, the mode's gather (none for
// direct; the photon estimate; or gather rays, with the irradiance cache where planned), and the
// shade pass.
template <class Device>
void run_gather_frame(Device& dev, const GeometryView& geometry, const LightSelection& lights,
                      const PhotonGatherPass& gather_template, const FramePlan& plan, Image& linear, AovImages& aovs,
                      StageTimes& times) {
    const std::uint64_t pixels = plan.pixels();
    constexpr bool packets = traces_packets_v<Device>;
    const bool final_gather = plan.mode() == RenderMode::final_gather;
    IrradianceCache fresh_cache(plan.settings.ic_accuracy, plan.cache_min_radius, plan.cache_max_radius);
    IrradianceCache& cache = plan.kept_cache ? *plan.kept_cache : fresh_cache;
    const std::uint64_t records_before = cache.tree.records().size(), points_before = cache.points;
    run_samples(dev, plan, linear, aovs, times, [&](const FrameBuffersView& fb, std::uint32_t s, auto& lap, auto& report) {
        const TracePass trace{geometry, plan.camera, fb, s, plan.settings.max_depth, plan.epsilon};
        if constexpr (packets)
            dev.launch(PacketTracePass::work_items(plan.width, plan.height), PacketTracePass{trace});
        else
            dev.launch(pixels, trace);
        times.ray_tracing_ms += lap();
        report(s, 1);

        if (plan.gather_photons()) {
            PhotonGatherPass gather = gather_template;
            gather.frame = fb;
            if (final_gather && plan.irradiance_cache)
                run_cached_gather(dev, cache, make_final_gather_pass(geometry, lights, gather, s, plan.settings, plan.epsilon),
                                  plan.camera);
            else if (final_gather)
                dev.launch(pixels, make_final_gather_pass(geometry, lights, gather, s, plan.settings, plan.epsilon));
            else if constexpr (gathers_by_tile_v<Device>)
                dev.launch(PhotonTileGatherPass::work_items(fb), PhotonTileGatherPass{gather});
            else
                dev.launch(pixels, gather);  // one item per pixel, over its vertices
            times.photon_gather_ms += lap();
            report(s, 2);
        }

        ShadePass shade{geometry, lights, fb, s, plan.settings.light_samples, plan.direct_light(),
                        plan.gather_photons(), plan.epsilon};
        dev.launch(pixels, shade);
        times.shading_ms += lap();
        report(s, 3);
    });
    times.cache_records = cache.tree.records().size() - records_before;
    times.cache_points = cache.points - points_before;
    times.cache_records_kept = records_before;
}

template <class Device>
void run_frame(Device& dev, const GeometryView& geometry, const LightSelection& lights,
               const PhotonGatherPass& gather_template, const FramePlan& plan, Image& linear, AovImages& aovs,
               StageTimes& times) {
    switch (plan.mode()) {
        case RenderMode::sppm:
            return run_sppm(dev, geometry, lights, plan.camera, plan.width, plan.height, plan.settings, plan.epsilon,
                            plan.sppm, linear, aovs, times);
        case RenderMode::path: return run_path_frame(dev, geometry, lights, plan, linear, aovs, times);
        case RenderMode::albedo:
            return run_samples(dev, plan, linear, aovs, times, [&](const FrameBuffersView& fb, std::uint32_t s, auto& lap, auto&) {
                dev.launch(plan.pixels(), AlbedoPass{geometry, plan.camera, fb, s});
                times.ray_tracing_ms += lap();
            });
        case RenderMode::photons:
        case RenderMode::direct_photons:
        case RenderMode::direct:
        case RenderMode::final_gather:
            return run_gather_frame(dev, geometry, lights, gather_template, plan, linear, aovs, times);
    }
}

}  // namespace kdpm
