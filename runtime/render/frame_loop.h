#pragma once
// One frame, written once for both backends: per sample, the trace, gather and shade passes
// over the frame arrays, then the sums come back to the host. `Device` supplies arrays
// (array<T>(n) zero-filled, scratch<T>(n) not), launches (launch(n, pass)) and copies to the host (to_host).
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/backend/items_on_host.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/render/aov_arrays.h"
#include "runtime/render/camera.h"
#include "runtime/render/packet_trace_pass.h"
#include "runtime/render/final_gather_pass.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/irradiance_cache.h"
#include "runtime/render/path_pass.h"
#include "runtime/render/photon_gather_pass.h"
#include "runtime/render/photon_tile_gather_pass.h"
#include "runtime/render/render_settings.h"
#include "runtime/render/sample_average.h"
#include "runtime/render/shade_pass.h"
#include "runtime/render/sppm_loop.h"
#include "runtime/render/stage_times.h"
#include "runtime/render/trace_pass.h"

namespace kdpm {

// Decided on the host from the settings and the scene, the same for both backends.
struct FramePlan {
    PinholeCamera camera;
    std::uint32_t width = 0, height = 0;
    RenderSettings settings;
    float epsilon = 1e-4f;
    bool gather_photons = false;
    bool direct_light = false;
    bool path_trace = false;  // --mode path: one path pass per sample instead of trace/gather/shade
    bool progressive = false;  // --mode sppm: the passes of sppm_loop.h instead of samples
    SppmPlan sppm;
    bool final_gather = false;  // --mode final-gather: the gather pass sends gather rays (needs gather_photons)
    bool irradiance_cache = false;  // final-gather: gather rays only at cache records (CPU backend)
    float cache_min_radius = 0.0f, cache_max_radius = 1e30f;  // clamp of the records' R_i (scene units)
    IrradianceCache* kept_cache = nullptr;  // records from earlier frames to use and extend; null: a new cache
};

template <class Device>
void run_frame(Device& dev, const GeometryView& geometry, const LightSelection& lights,
               const PhotonGatherPass& gather_template,
               const FramePlan& plan, Image& linear, AovImages& aovs, StageTimes& times) {
    if (plan.progressive)
        return run_sppm(dev, geometry, lights, plan.camera, plan.width, plan.height, plan.settings, plan.epsilon,
                        plan.sppm, linear, aovs, times);
    const std::uint64_t pixels = static_cast<std::uint64_t>(plan.width) * plan.height;
    // The path pass keeps its vertices in registers: only the sums and the AOVs.
    const std::uint64_t per_pixel = plan.path_trace ? 0 : pixels;
    const std::uint64_t slots = per_pixel * kMaxDiffuseVertices;
    const AovSet& want = plan.settings.aovs;
    StopWatch watch;

    // Only the sums start at zero; the trace pass writes every pixel's emitted light, vertex
    // count and AOVs, and the later passes read only the vertex slots it filled.
    auto accum = dev.template array<glm::vec3>(pixels);
    auto emitted = dev.template scratch<glm::vec3>(per_pixel);
    auto vertex_count = dev.template scratch<std::uint32_t>(per_pixel);
    auto vertices = dev.template scratch<DiffuseVertex>(slots);
    auto gathered = dev.template scratch<glm::vec3>(plan.gather_photons ? slots : 0);
    const AovArrays<Device> aov_arrays(dev, want, pixels);
    constexpr bool packets = requires { requires Device::traces_packets; };

    FrameBuffersView fb;
    fb.width = plan.width;
    fb.height = plan.height;
    fb.emitted = plan.path_trace ? nullptr : emitted.data();
    fb.vertex_count = plan.path_trace ? nullptr : vertex_count.data();
    fb.vertices = plan.path_trace ? nullptr : vertices.data();
    fb.gathered = plan.gather_photons ? gathered.data() : nullptr;
    fb.accum = accum.data();
    aov_arrays.name_in(fb);
    times.transfer_ms += watch.lap_ms();

    const std::uint32_t spp = plan.settings.spp < 1 ? 1 : plan.settings.spp;
    // The samples first .. end - 1 of the run (Renderer::render checked that they fit).
    const std::uint32_t first = plan.settings.first_sample, end = first + spp;
    auto report = [&](std::uint32_t sample, int passes_done) {
        if (plan.settings.progress) plan.settings.progress(((sample - first) * 3.0 + passes_done) / (3.0 * spp));
    };
    for (std::uint32_t s = first; s < end && plan.path_trace; ++s) {
        PathPass path{geometry, lights, plan.camera, fb, s, plan.settings.max_depth, plan.settings.max_bounces,
                      plan.epsilon};
        dev.launch(pixels, path);
        times.ray_tracing_ms += watch.lap_ms();
        report(s, 3);
    }
    IrradianceCache fresh_cache(plan.settings.ic_accuracy, plan.cache_min_radius, plan.cache_max_radius);
    IrradianceCache& cache = plan.kept_cache ? *plan.kept_cache : fresh_cache;
    const std::uint64_t records_before = cache.tree.records().size(), points_before = cache.points;
    for (std::uint32_t s = first; s < end && !plan.path_trace; ++s) {
        const TracePass trace{geometry, plan.camera, fb, s, plan.settings.max_depth, plan.epsilon};
        if constexpr (packets)
            dev.launch(PacketTracePass::work_items(plan.width, plan.height), PacketTracePass{trace});
        else
            dev.launch(pixels, trace);
        times.ray_tracing_ms += watch.lap_ms();
        report(s, 1);

        if (plan.gather_photons) {
            PhotonGatherPass gather = gather_template;
            gather.frame = fb;
            if (plan.final_gather && plan.irradiance_cache)
                run_cached_gather(dev, cache, make_final_gather_pass(geometry, gather, s, plan.settings.gather_rays,
                                                                     plan.settings.max_depth, plan.epsilon));
            else if (plan.final_gather)
                dev.launch(pixels, make_final_gather_pass(geometry, gather, s, plan.settings.gather_rays,
                                                          plan.settings.max_depth, plan.epsilon));
            else if constexpr (requires { requires Device::gathers_by_tile; })
                dev.launch(PhotonTileGatherPass::work_items(fb), PhotonTileGatherPass{gather});
            else
                dev.launch(pixels, gather);  // one item per pixel, over its vertices
            times.photon_gather_ms += watch.lap_ms();
            report(s, 2);
        }

        ShadePass shade{geometry, lights, fb, s, plan.settings.light_samples, plan.direct_light,
                        plan.gather_photons, plan.epsilon};
        dev.launch(pixels, shade);
        times.shading_ms += watch.lap_ms();
        report(s, 3);
    }

    times.cache_records = cache.tree.records().size() - records_before;
    times.cache_points = cache.points - points_before;
    times.cache_records_kept = records_before;

    std::vector<glm::vec3> copied;  // only where the device's arrays are not host memory
    const glm::vec3* sums = items_on_host(dev, accum, copied);
    average_samples(sums, plan.width, plan.height, 1.0f / static_cast<float>(spp), linear);

    aov_arrays.to_host(dev, aovs);
    times.transfer_ms += watch.lap_ms();
}

}  // namespace kdpm
