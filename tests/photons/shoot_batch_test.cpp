// The shooting loop's batch size (65,536 paths on the CPU, up to 2^20 on CUDA) never changes the
// hits: every path writes only its own slots and the compaction is in path order. This is what
// lets the two backends' files be compared path for path.
#include <catch2/catch.hpp>

#include <cstring>

#include "runtime/backend/cpu_device.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/photons/shoot_loop.h"
#include "runtime/shading/light_power_table.h"
#include "runtime/shading/ray_offset.h"
#include "tests/photons/shooting_scenes.h"

using namespace kdpm;

TEST_CASE("the shooting loop gives the same hits whatever the batch size", "[photons][shoot]") {
    auto box = test::closed_box(0.7f, /*mirror_floor=*/true);
    const GeometryView g = box.view();
    const LightPowerTable lights = light_power_table(g);
    const LightSelection table = lights.selection();
    ShootSettings settings;
    settings.emitted_count = 5000;
    settings.max_bounces = 6;
    settings.seed = 9;
    settings.ray_offset = photon_ray_offset(g.info);

    CpuDevice device;
    std::vector<PhotonHit> one_batch, small_batches;
    const std::uint64_t rays_one = shoot_paths(device, g, table, settings, 0, 5000, 5000, one_batch, {});
    double last_progress = 0;
    int reports = 0;
    const std::uint64_t rays_small = shoot_paths(device, g, table, settings, 0, 5000, 1024, small_batches,
                                                 [&](double f) { last_progress = f, ++reports; });
    REQUIRE(one_batch.size() > 5000);
    CHECK(rays_one == rays_small);
    REQUIRE(one_batch.size() == small_batches.size());
    CHECK(std::memcmp(one_batch.data(), small_batches.data(), one_batch.size() * sizeof(PhotonHit)) == 0);
    CHECK(reports == 5);  // ceil(5000 / 1024) batches
    CHECK(last_progress == 1.0);
    // And the public entry point (CPU) gives the same hits as the loop.
    ShootOptions options;
    options.photons = 5000;
    options.max_bounces = 6;
    options.seed = 9;
    const ShotPhotons shot = shoot_photons(g, options);
    REQUIRE(shot.hits.size() == one_batch.size());
    CHECK(std::memcmp(shot.hits.data(), one_batch.data(), one_batch.size() * sizeof(PhotonHit)) == 0);
    CHECK(shoot_batch_size(4, 1u << 16, 256u << 20) == 1u << 16);  // the preferred size when it fits
    CHECK(shoot_batch_size(6, 1u << 20, 64u << 20) == (64u << 20) / (7 * sizeof(PhotonHit)));  // else the budget
    CHECK(shoot_batch_size(255, 1u << 20, 1u << 10) == 1024);  // never below 1024 paths
}

TEST_CASE("both path orders append exactly each path's own photons, in path order, after those already there",
          "[photons][shoot]") {
    auto box = test::closed_box_with_glass_cube(0.8f);
    const GeometryView g = box.view();
    const LightPowerTable lights = light_power_table(g);
    ShootSettings settings;
    settings.emitted_count = 3000;
    settings.max_bounces = 8;
    settings.seed = 4;
    settings.ray_offset = photon_ray_offset(g.info);
    // The reference: one path after another, each traced on its own into its own slots.
    const PhotonHit marker = [] {
        PhotonHit h{};
        h.path = 0xdeadbeefu;
        return h;
    }();
    std::vector<PhotonHit> reference{marker, marker};
    std::uint64_t reference_rays = 0;
    std::vector<PhotonHit> out(settings.max_bounces + 1);
    for (std::uint64_t path = 500; path < 2700; ++path) {
        const PhotonPathResult r = trace_photon_path(g, lights.selection(), settings, path, out.data());
        reference_rays += r.rays;
        reference.insert(reference.end(), out.begin(), out.begin() + r.stored);
    }
    REQUIRE(reference.size() > 2200);
    for (const PathOrder order : {PathOrder::depth_first, PathOrder::sorted_waves}) {
        CpuDevice device;
        std::vector<PhotonHit> hits{marker, marker};
        const std::uint64_t rays = shoot_paths(device, g, lights.selection(), settings, 500, 2700, 1024, hits, {},
                                               KdTreeClosestHit{}, order);
        CHECK(rays == reference_rays);
        REQUIRE(hits.size() == reference.size());
        CHECK(std::memcmp(hits.data(), reference.data(), hits.size() * sizeof(PhotonHit)) == 0);
    }
}
