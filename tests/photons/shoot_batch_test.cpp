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
