#pragma once
// --mode sppm, written once for both backends: per pass, the visible points, a fresh set of
// photons from the runtime's shooting kernel (shoot_paths, seed = pass index, so passes are
// independent and the image is a pure function of the settings), the photons' grid (host) and
// the per-pixel gather and update (sppm_passes.h). `dev` holds the per-pixel statistics for the
// whole frame; a second Device of the same kind holds each pass's photon batches and grid, since
// shoot_paths starts its device afresh (begin()) for every batch.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "runtime/geometry/geometry_view.h"
#include "runtime/photons/shoot_loop.h"
#include "runtime/render/aov_arrays.h"
#include "runtime/render/camera.h"
#include "runtime/render/frame_buffers.h"
#include "runtime/render/image/image.h"
#include "runtime/render/render_settings.h"
#include "runtime/render/sppm/sppm_passes.h"
#include "runtime/render/sppm/sppm_photon_grid.h"
#include "runtime/render/stage_times.h"

namespace kdpm {

struct SppmPlan {
    std::uint32_t passes = 1;
    std::uint64_t photons_per_pass = 0;
    float initial_radius = 0.0f;
    float photon_ray_offset = 1e-4f;
    // Photons of bounce 1 .. this are gathered (bounce 0 is the direct light, by shadow rays):
    // max_bounces - 1 of --max-bounces, so that both modes count the same diffuse vertices.
    std::uint32_t max_photon_bounce = 0;
};

template <class Device>
void run_sppm(Device& dev, const GeometryView& geometry, const LightSelection& lights, const PinholeCamera& camera,
              std::uint32_t width, std::uint32_t height, const RenderSettings& settings, float epsilon,
              const SppmPlan& sppm, Image& linear, AovImages& aovs, StageTimes& times) {
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
    const AovSet& want = settings.aovs;
    StopWatch watch;

    std::vector<SppmPixel> start(pixels);
    for (SppmPixel& p : start) p.radius2 = sppm.initial_radius * sppm.initial_radius;
    auto state = dev.from_host(start);
    auto points = dev.template scratch<SppmVisiblePoint>(pixels);
    const AovArrays<Device> aov_arrays(dev, want, pixels);
    FrameBuffersView fb;
    fb.width = width;
    fb.height = height;
    aov_arrays.name_in(fb);

    Device pass_dev;
    ShootSettings shoot;
    shoot.emitted_count = sppm.photons_per_pass;
    shoot.max_bounces = sppm.max_photon_bounce;
    shoot.ray_offset = sppm.photon_ray_offset;
    const std::uint64_t batch = shoot_batch_size(shoot.max_bounces, 1u << 16, 64u << 20);
    std::vector<PhotonHit> hits;
    std::vector<SppmPixel> host_state;
    times.transfer_ms += watch.lap_ms();

    // This pass's photons (seed = pass), gathered by every visible point within its radius.
    auto photon_pass = [&](std::uint32_t pass, float cell) {
        hits.clear();
        shoot.seed = pass;
        shoot_paths(pass_dev, geometry, lights, shoot, 0, sppm.photons_per_pass, batch, hits, {}, KdTreeClosestHit{},
                    PathOrder::sorted_waves);  // depth first where the device is not the CPU
        times.shading_ms += watch.lap_ms();  // photon shooting: this mode's "shading" row
        SppmPhotonGrid grid = build_sppm_photon_grid(hits, 1, sppm.max_photon_bounce, cell);
        pass_dev.begin();
        auto photons = pass_dev.from_host(grid.photons);
        auto buckets = pass_dev.from_host(grid.bucket_start);
        grid.view.photons = photons.data();
        grid.view.bucket_start = buckets.data();
        times.transfer_ms += watch.lap_ms();
        dev.launch(pixels, SppmGatherPass{grid.view, state.data(), points.data()});
        times.photon_gather_ms += watch.lap_ms();
    };

    for (std::uint32_t pass = 0; pass < sppm.passes; ++pass) {
        dev.launch(pixels, SppmVisiblePass{geometry, lights, camera, fb, state.data(), points.data(), pass,
                                           settings.max_depth, settings.light_samples, epsilon});
        times.ray_tracing_ms += watch.lap_ms();
        if (sppm.max_photon_bounce > 0) {  // else direct light only: no photon would be gathered
            // The largest radius left is the grid's cell side: a query spans at most 2 cells per axis.
            dev.to_host(state, host_state);
            float largest2 = 0.0f;
            for (const SppmPixel& p : host_state) largest2 = std::max(largest2, p.radius2);
            times.transfer_ms += watch.lap_ms();
            photon_pass(pass, std::sqrt(largest2));
        }
        if (settings.progress) settings.progress(static_cast<double>(pass + 1) / sppm.passes);
    }

    dev.to_host(state, host_state);
    linear.reshape(static_cast<int>(width), static_cast<int>(height));  // every pixel written below
    for (std::uint64_t i = 0; i < pixels; ++i) {
        const glm::vec3 l = sppm_radiance(host_state[i], sppm.passes);
        for (int c = 0; c < 3; ++c) linear.rgb[i * 3 + c] = l[c];
    }
    aov_arrays.to_host(dev, aovs);
    times.transfer_ms += watch.lap_ms();
}

}  // namespace kdpm
