#pragma once
// shoot_photons' CPU half with the closest-hit query as a parameter: the same checks, light
// table, settings, batches, launch grain and summary as shoot_photons, so that a peer which
// swaps in another intersector (kdpm-bench's Embree photon tracer) differs in nothing else but
// the path order it is fastest with.
#include <cstdint>
#include <functional>

#include "runtime/backend/cpu_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/photons/photon_path.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/photons/shoot_loop.h"
#include "runtime/shading/light_power_table.h"

namespace kdpm {

// Everything a shooting run needs before its first path (photon_shooter.cpp).
struct ShootPlan {
    LightPowerTable lights;
    ShootSettings settings;
    std::uint64_t first_path = 0, end_path = 0;
};

// Throws std::invalid_argument as shoot_photons documents.
ShootPlan plan_shooting(const GeometryView& g, const ShootOptions& options);

// Fills shot.info (emitted count and power, bounce limit, stored and caustic counts, bounds).
void summarize_shot(const GeometryView& g, const ShootOptions& options, ShotPhotons& shot);

// CPU batches: 64 Ki paths, or fewer when their room for max_bounces + 1 photons a path would pass
// 256 MiB. Larger batches would sort more rays together, but their fresh pages cost more than that
// gains.
inline std::uint64_t cpu_shoot_batch_size(std::uint32_t max_bounces) {
    return shoot_batch_size(max_bounces, 1u << 16, 256u << 20);
}

// kdpm shoots in sorted waves because they trace faster than depth first with its kd-tree; a peer
// passes the order that is fastest for its intersector.
template <class ClosestHit = KdTreeClosestHit>
ShotPhotons shoot_photons_on_cpu(const GeometryView& g, const ShootOptions& options, const ClosestHit& intersect = {},
                                 const std::function<void(double)>& progress = {},
                                 PathOrder order = PathOrder::sorted_waves) {
    const ShootPlan plan = plan_shooting(g, options);
    ShotPhotons shot;
    CpuDevice device;
    shot.rays = shoot_paths(device, g, plan.lights.selection(), plan.settings, plan.first_path, plan.end_path,
                            cpu_shoot_batch_size(options.max_bounces), shot.hits, progress, intersect, order);
    summarize_shot(g, options, shot);
    return shot;
}

}  // namespace kdpm
