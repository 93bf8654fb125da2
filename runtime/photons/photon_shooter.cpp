#include "runtime/photons/photon_shooter.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "formats/photon_hits_summary.h"
#include "runtime/backend/cpu_device.h"
#include "runtime/photons/photon_shooter_cuda.h"
#include "runtime/photons/shoot_loop.h"

namespace kdpm {

LightDistribution LightDistribution::of(const GeometryView& g) {
    LightDistribution d;
    double total = 0.0;
    for (std::uint32_t i = 0; i < g.light_count; ++i) {
        float p = g.lights[i].power;
        total += std::isfinite(p) && p > 0.0f ? p : 0.0f;
    }
    d.total_power = static_cast<float>(total);
    double running = 0.0;
    for (std::uint32_t i = 0; i < g.light_count; ++i) {
        float p = g.lights[i].power;
        running += std::isfinite(p) && p > 0.0f ? p : 0.0f;
        d.cdf.push_back(total > 0.0 ? static_cast<float>(running / total) : 0.0f);
    }
    if (!d.cdf.empty() && total > 0.0) {
        // Exactly 1 at the last light with power, so every u < 1 finds a light with power.
        for (std::size_t i = d.cdf.size(); i-- > 0;) {
            if (g.lights[i].power > 0.0f) {
                for (std::size_t j = i; j < d.cdf.size(); ++j) d.cdf[j] = 1.0f;
                break;
            }
        }
    }
    return d;
}

LightTable LightDistribution::table(const GeometryView& g) const {
    return LightTable{g.lights, cdf.data(), g.light_count, total_power};
}

float photon_ray_offset(const GeometryInfo& info) {
    float extent = 0.0f;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, info.bounds_max[a] - info.bounds_min[a]);
    return std::max(1e-5f * extent, 1e-6f);
}

ShotPhotons shoot_photons(const GeometryView& g, const ShootOptions& options,
                          const std::function<void(double)>& progress) {
    if (options.photons > 0xffffffffull) throw std::invalid_argument("at most 4294967295 photons");
    if (options.max_bounces > 255) throw std::invalid_argument("at most 255 bounces");
    LightDistribution lights = LightDistribution::of(g);
    if (!(lights.total_power > 0.0f)) throw std::invalid_argument("the scene has no light that emits");
    const LightTable table = lights.table(g);

    ShootSettings settings;
    settings.emitted_count = options.photons;
    settings.max_bounces = options.max_bounces;
    settings.seed = options.seed;
    settings.ray_offset = photon_ray_offset(g.info);

    ShotPhotons shot;
    if (options.backend == BackendKind::cuda) {
        shot.rays = shoot_paths_on_cuda(g, lights, settings, options.photons, shot.hits, progress);
    } else {
        CpuDevice device;
        shot.rays = shoot_paths(device, g, table, settings, options.photons,
                                shoot_batch_size(options.max_bounces, 1u << 16, 256u << 20), shot.hits, progress);
    }

    auto& info = shot.info;
    info.emitted_count = options.photons;
    info.max_bounces = options.max_bounces;
    for (std::uint32_t i = 0; i < g.light_count; ++i) {
        const AreaLightRecord& l = g.lights[i];
        if (!(l.power > 0.0f)) continue;
        for (int c = 0; c < 3; ++c) info.emitted_power[c] += kPhotonPi * l.area * l.radiance[c];
    }
    summarize_photon_hits(shot.hits, info);
    return shot;
}

}  // namespace kdpm
