#include "runtime/photons/photon_shooter.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "formats/photon_hits_summary.h"
#include "runtime/backend/cpu_device.h"
#include "runtime/photons/photon_shooter_cuda.h"
#include "runtime/photons/shoot_loop.h"
#include "runtime/shading/light_power_table.h"

namespace kdpm {

ShotPhotons shoot_photons(const GeometryView& g, const ShootOptions& options,
                          const std::function<void(double)>& progress) {
    if (options.photons > 0xffffffffull) throw std::invalid_argument("at most 4294967295 photons");
    if (options.max_bounces > 255) throw std::invalid_argument("at most 255 bounces");
    const std::uint64_t first_path = options.path_begin;
    const std::uint64_t end_path = options.path_end == 0 ? options.photons : options.path_end;
    if (!(first_path < end_path && end_path <= options.photons))
        throw std::invalid_argument("path range " + std::to_string(first_path) + ":" + std::to_string(end_path) +
                                    " is not within 0:" + std::to_string(options.photons));
    const LightPowerTable lights = light_power_table(g);
    if (!(lights.total_power > 0.0f)) throw std::invalid_argument("the scene has no light that emits");
    const LightSelection table = lights.selection();

    ShootSettings settings;
    settings.emitted_count = options.photons;
    settings.max_bounces = options.max_bounces;
    settings.seed = options.seed;
    settings.ray_offset = photon_ray_offset(g.info);

    ShotPhotons shot;
    if (options.backend == BackendKind::cuda) {
        shot.rays = shoot_paths_on_cuda(g, lights, settings, first_path, end_path, shot.hits, progress);
    } else {
        CpuDevice device;
        shot.rays = shoot_paths(device, g, table, settings, first_path, end_path,
                                shoot_batch_size(options.max_bounces, 1u << 16, 256u << 20), shot.hits, progress);
    }

    auto& info = shot.info;
    info.emitted_count = options.photons;
    info.max_bounces = options.max_bounces;
    for (std::uint32_t i = 0; i < g.light_count; ++i) {
        const AreaLightRecord& l = g.lights[i];
        if (!(l.power > 0.0f)) continue;
        for (int c = 0; c < 3; ++c) info.emitted_power[c] += kPi * l.area * l.radiance[c];
    }
    summarize_photon_hits(shot.hits, info);
    return shot;
}

}  // namespace kdpm
