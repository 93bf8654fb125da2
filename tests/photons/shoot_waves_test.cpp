// The CPU shooter's sorted waves (shoot_waves.h) store exactly the photons of depth-first paths:
// the same hits, bit for bit and in the same order, the same ray count, whatever the batch size
// or the thread count, with mirrors, glass and two lights.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <tbb/global_control.h>

#include "runtime/backend/cpu_device.h"
#include "runtime/photons/shoot_loop.h"
#include "runtime/photons/shoot_on_cpu.h"
#include "runtime/shading/light_power_table.h"
#include "runtime/shading/ray_offset.h"
#include "tests/photons/shooting_scenes.h"

using namespace kdpm;

namespace {

struct Shot {
    std::vector<PhotonHit> hits;
    std::uint64_t rays = 0;
};

Shot shoot(const GeometryView& g, const ShootSettings& settings, std::uint64_t batch, PathOrder order) {
    const LightPowerTable lights = light_power_table(g);
    CpuDevice device;
    Shot shot;
    shot.rays = shoot_paths(device, g, lights.selection(), settings, 0, settings.emitted_count, batch, shot.hits, {},
                            KdTreeClosestHit{}, order);
    return shot;
}

bool same_hits(const Shot& a, const Shot& b) {
    return a.rays == b.rays && a.hits.size() == b.hits.size() &&
           std::memcmp(a.hits.data(), b.hits.data(), a.hits.size() * sizeof(PhotonHit)) == 0;
}

}  // namespace

TEST_CASE("sorted waves store the photons of depth-first paths", "[photons][shoot]") {
    struct Case {
        const char* name;
        GeometryFile scene;
        std::uint32_t bounces;
    };
    std::vector<Case> cases;
    cases.push_back({"mirror floor", test::closed_box(0.7f, /*mirror_floor=*/true), 6});
    cases.push_back({"glass cube", test::closed_box_with_glass_cube(0.8f), 8});
    cases.push_back({"two lights", test::closed_box_two_lights(0.5f), 4});
    for (const Case& c : cases) {
        const GeometryView g = c.scene.view();
        ShootSettings settings;
        settings.emitted_count = 20000;
        settings.max_bounces = c.bounces;
        settings.seed = 3;
        settings.ray_offset = photon_ray_offset(g.info);
        INFO(c.name);
        const Shot reference = shoot(g, settings, 20000, PathOrder::depth_first);
        REQUIRE(reference.hits.size() > settings.emitted_count);  // most paths store more than one hit
        CHECK(same_hits(shoot(g, settings, 20000, PathOrder::sorted_waves), reference));
        CHECK(same_hits(shoot(g, settings, 1024, PathOrder::sorted_waves), reference));
        {
            tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
            CHECK(same_hits(shoot(g, settings, 20000, PathOrder::sorted_waves), reference));
        }
    }
}

TEST_CASE("the CPU shooter's default order gives the depth-first photons", "[photons][shoot]") {
    auto scene = test::closed_box_with_glass_cube(0.7f);
    const GeometryView g = scene.view();
    ShootOptions options;
    options.photons = 6000;
    options.max_bounces = 5;
    options.seed = 11;
    const ShotPhotons picked = shoot_photons_on_cpu(g, options);
    const ShotPhotons depth_first = shoot_photons_on_cpu(g, options, KdTreeClosestHit{}, {}, PathOrder::depth_first);
    CHECK(picked.rays == depth_first.rays);
    REQUIRE(picked.hits.size() == depth_first.hits.size());
    CHECK(std::memcmp(picked.hits.data(), depth_first.hits.data(), depth_first.hits.size() * sizeof(PhotonHit)) == 0);
    CHECK(picked.info.stored_count == depth_first.info.stored_count);
}

TEST_CASE("a wave's sort key puts rays close in origin and direction together", "[photons][shoot]") {
    GeometryInfo info{};
    for (int a = 0; a < 3; ++a) {
        info.bounds_min[a] = -2.0f;
        info.bounds_max[a] = 2.0f;
    }
    info.bounds_max[2] = -2.0f;  // a flat scene: no extent along z
    const shoot_waves_detail::WaveKey key(info);
    auto state = [](glm::vec3 o, glm::vec3 d) {
        PhotonPathState s;
        s.origin = o;
        s.direction = d;
        return s;
    };
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    const std::uint32_t low_corner = key(state({-2.0f, -2.0f, -2.0f}, {-1.0f, -1.0f, -1.0f}));
    CHECK(low_corner == 0u);
    // The top bit is the origin's x half; every key fits 30 bits.
    CHECK(key(state({0.5f, -2.0f, -2.0f}, up)) >= (1u << 29));
    CHECK(key(state({-0.5f, 1.9f, 0.0f}, up)) < (1u << 29));
    CHECK(key(state({1.99f, 1.99f, 5.0f}, {1.0f, 1.0f, 1.0f})) < (1u << 30));
    // Rays within one cell of origin and direction share the key; outside the bounds clamps.
    CHECK(key(state({0.01f, 0.01f, 0.0f}, up)) == key(state({0.02f, 0.02f, 0.0f}, up)));
    CHECK(key(state({9.0f, 0.0f, 0.0f}, up)) == key(state({1.99f, 0.0f, 0.0f}, up)));
    // Nearby rays sort closer together than rays across the scene.
    const std::uint32_t a = key(state({0.3f, 0.3f, 0.0f}, up));
    const std::uint32_t near = key(state({0.45f, 0.3f, 0.0f}, up));
    const std::uint32_t far = key(state({-1.7f, 1.6f, 0.0f}, up));
    CHECK((a > near ? a - near : near - a) < (a > far ? a - far : far - a));
    // A NaN coordinate takes cell 0 instead of an undefined conversion.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK(key(state({nan, -2.0f, -2.0f}, {-1.0f, -1.0f, -1.0f})) == 0u);
}
