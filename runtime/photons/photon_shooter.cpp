#include "runtime/photons/photon_shooter.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "formats/photon_hits_summary.h"
#include "runtime/photons/photon_shooter_cuda.h"
#include "runtime/photons/shoot_on_cpu.h"

namespace kdpm {

ShootPlan plan_shooting(const GeometryView& g, const ShootOptions& options) {
    if (options.photons > 0xffffffffull) throw std::invalid_argument("at most 4294967295 photons");
    if (options.max_bounces > 255) throw std::invalid_argument("at most 255 bounces");
    ShootPlan plan;
    plan.first_path = options.path_begin;
    plan.end_path = options.path_end == 0 ? options.photons : options.path_end;
    if (!(plan.first_path < plan.end_path && plan.end_path <= options.photons))
        throw std::invalid_argument("path range " + std::to_string(plan.first_path) + ":" +
                                    std::to_string(plan.end_path) + " is not within 0:" +
                                    std::to_string(options.photons));
    plan.lights = light_power_table(g);
    if (!(plan.lights.total_power > 0.0f)) throw std::invalid_argument("the scene has no light that emits");

    plan.settings.emitted_count = options.photons;
    plan.settings.max_bounces = options.max_bounces;
    plan.settings.seed = options.seed;
    plan.settings.ray_offset = photon_ray_offset(g.info);
    return plan;
}

void summarize_shot(const GeometryView& g, const ShootOptions& options, ShotPhotons& shot) {
    auto& info = shot.info;
    info.emitted_count = options.photons;
    info.max_bounces = options.max_bounces;
    for (std::uint32_t i = 0; i < g.light_count; ++i) {
        const AreaLightRecord& l = g.lights[i];
        if (!(l.power > 0.0f)) continue;
        for (int c = 0; c < 3; ++c) info.emitted_power[c] += kPi * l.area * l.radiance[c];
    }
    summarize_photon_hits(shot.hits, info);
}

ShotPhotons shoot_photons(const GeometryView& g, const ShootOptions& options,
                          const std::function<void(double)>& progress) {
    if (options.backend != BackendKind::cuda) return shoot_photons_on_cpu(g, options, KdTreeClosestHit{}, progress);
    const ShootPlan plan = plan_shooting(g, options);
    ShotPhotons shot;
    shot.rays = shoot_paths_on_cuda(g, plan.lights, plan.settings, plan.first_path, plan.end_path, shot.hits, progress);
    summarize_shot(g, options, shot);
    return shot;
}

}  // namespace kdpm
