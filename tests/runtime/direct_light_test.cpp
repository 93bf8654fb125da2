// Direct light against the closed form: the irradiance at a point from a uniform polygonal
// emitter (Lambert's formula), times albedo / pi, is the radiance the renderer must return.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include "runtime/geometry/scene_traversal.h"
#include "runtime/render/renderer.h"
#include "runtime/shading/direct_light.h"
#include "runtime/shading/light_power_table.h"
#include "runtime/shading/ray_offset.h"
#include "runtime/shading/surface_point.h"
#include "tests/runtime/built_scene.h"
#include "tests/runtime/hand_built_scene.h"

using namespace kdpm;

namespace {

// Lambert's polygon formula: E = L/2 * sum_i angle(r_i, r_i+1) * n . unit(r_i x r_i+1).
double polygon_irradiance(const std::vector<glm::dvec3>& corners, glm::dvec3 x, glm::dvec3 n, double radiance) {
    double sum = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        glm::dvec3 a = glm::normalize(corners[i] - x), b = glm::normalize(corners[(i + 1) % corners.size()] - x);
        sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return 0.5 * radiance * std::fabs(sum);
}

}  // namespace

TEST_CASE("direct light at a floor point matches the polygon irradiance formula", "[render]") {
    test::HandBuiltScene scene;
    const glm::vec3 albedo(0.8f, 0.5f, 0.25f);
    scene.add_quad({-10, 0, -10}, {0, 0, 20}, {20, 0, 0}, scene.add_material(albedo));
    // Off-centre, tilted-free parallelogram light facing down, 1 unit above the floor.
    const glm::vec3 p0(-0.2f, 1.0f, -0.4f), e1(1.0f, 0.0f, 0.0f), e2(0.0f, 0.0f, 0.6f);
    const float le = 5.0f;
    scene.add_parallelogram_light(p0, e1, e2, glm::vec3(le));
    scene.set_camera({0, 3, 0}, {0, 0, 0}, {0, 0, 1}, 10.0f, 3, 3);
    SceneViews views = scene.views();

    Renderer renderer(views, BackendKind::cpu);
    RenderSettings settings;
    settings.mode = RenderMode::direct;
    settings.light_samples = 64 * 64;
    RenderResult r = renderer.render(settings);

    const std::vector<glm::dvec3> corners{glm::dvec3(p0), glm::dvec3(p0 + e1), glm::dvec3(p0 + e1 + e2),
                                          glm::dvec3(p0 + e2)};
    const double e = polygon_irradiance(corners, glm::dvec3(0.0), glm::dvec3(0, 1, 0), le);
    const std::size_t centre = 4;  // pixel (1, 1)
    for (int c = 0; c < 3; ++c) {
        const double expected = albedo[c] / 3.14159265358979 * e;
        INFO("channel " << c << " expected " << expected << " got " << r.linear.rgb[centre * 3 + c]);
        CHECK(r.linear.rgb[centre * 3 + c] == Approx(expected).epsilon(0.005));
    }
}

TEST_CASE("an occluder between floor and light leaves the floor point dark", "[render]") {
    test::HandBuiltScene scene;
    scene.add_quad({-10, 0, -10}, {0, 0, 20}, {20, 0, 0}, scene.add_material(glm::vec3(0.8f)));
    // A small blocker at height 0.5 that covers the light as seen from the origin (from below:
    // its back side faces the floor, which must still block).
    scene.add_quad({-1, 0.5f, -1}, {0, 0, 2}, {2, 0, 0}, scene.add_material(glm::vec3(0.8f)));
    scene.add_parallelogram_light({-0.2f, 1.0f, -0.2f}, {0.4f, 0, 0}, {0, 0, 0.4f}, glm::vec3(5.0f));
    scene.set_camera({0, 0.25f, 0.01f}, {0, 0, 0}, {0, 0, 1}, 5.0f, 1, 1);
    SceneViews views = scene.views();
    Renderer renderer(views, BackendKind::cpu);
    RenderSettings settings;
    settings.mode = RenderMode::direct;
    RenderResult r = renderer.render(settings);
    CHECK(r.linear.rgb[0] == 0.0f);
}

TEST_CASE("direct light from shadow-ray packets equals one shadow ray at a time", "[render][packets]") {
    // The CPU walks a point's shadow rays 16 at a time as packets (direct_light_with); the
    // reference here traces each alone with occluded(), in the same order: the same bits.
    test::BuiltScene scene(3000, 7, 8, 8);
    const GeometryView& g = scene.views.geometry;
    const LightPowerTable table = light_power_table(g);
    const LightSelection lights = table.selection();
    REQUIRE(lights.count == 1);
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int points = 0, lit = 0, shadowed = 0;
    for (int trial = 0; trial < 400; ++trial) {
        // A point on the soup: where a random ray from above first meets it.
        const Ray probe{glm::vec3(u(rng), 2.0f, u(rng)), 0.0f, glm::vec3(0.3f * u(rng), -1.0f, 0.3f * u(rng)), 1e30f};
        const Hit hit = closest_hit(g, probe);
        if (!hit.found()) continue;
        ++points;
        const SurfacePoint s = surface_at(g, probe, hit);
        const glm::vec3 n = s.geometric_normal;  // facing the probe, as the renderer's vertices do
        const glm::vec3 origin = offset_origin(s.position, n, render_ray_offset(g.info), true);
        const glm::vec3 albedo(0.7f, 0.5f, 0.3f);
        for (std::uint32_t samples : {1u, 5u, 16u, 64u}) {
            const ShadingRandom random{static_cast<std::uint32_t>(trial), samples};
            const glm::vec3 packed = direct_light_with(g, lights, origin, n, albedo, samples, random);
            std::uint32_t side = 1;
            while (side * side < samples) ++side;
            glm::vec3 irradiance(0.0f);
            for (std::uint32_t j = 0; j < side * side; ++j) {
                Ray shadow;
                glm::vec3 e;
                if (!light_sample(g, lights, origin, n, j, side, random, shadow, e)) continue;
                if (occluded(g, shadow)) {
                    ++shadowed;
                    continue;
                }
                ++lit;
                irradiance += e;
            }
            const glm::vec3 single = lambert_brdf(albedo) * irradiance / static_cast<float>(side * side);
            INFO("trial " << trial << ", " << samples << " samples");
            CHECK(std::memcmp(&packed, &single, sizeof packed) == 0);
        }
    }
    // The soup both hides and shows the light from many of its points.
    CHECK(points > 100);
    CHECK(lit > 1000);
    CHECK(shadowed > 1000);
}

TEST_CASE("a dim light right beside the point gets its share of shadow rays, not its share of power",
          "[render][lights]") {
    // A 2 x 2 light 3 units above the point and a 1 cm light 2 cm above it, equally bright: the
    // small one has 1/40000 of the power but gives a third of the irradiance. Picked by power
    // alone it is met once in ~2500 estimates of 16 rays, then weighs 40000: the estimates'
    // spread is many times their mean (20x here).
    test::HandBuiltScene scene;
    scene.add_quad({-10, 0, -10}, {0, 0, 20}, {20, 0, 0}, scene.add_material(glm::vec3(0.5f)));
    const glm::vec3 big_p0(-1.0f, 3.0f, -1.0f), big_e1(2, 0, 0), big_e2(0, 0, 2);
    const glm::vec3 small_p0(-0.005f, 0.02f, -0.005f), small_e1(0.01f, 0, 0), small_e2(0, 0, 0.01f);
    scene.add_parallelogram_light(big_p0, big_e1, big_e2, glm::vec3(10.0f));
    scene.add_parallelogram_light(small_p0, small_e1, small_e2, glm::vec3(10.0f));
    scene.set_camera({0, 2, 0.01f}, {0, 0, 0}, {0, 0, 1}, 5.0f, 1, 1);
    SceneViews views = scene.views();
    const GeometryView& g = views.geometry;
    const LightPowerTable table = light_power_table(g);
    const LightSelection lights = table.selection();
    REQUIRE(lights.count == 2);
    auto corners = [](glm::vec3 p0, glm::vec3 e1, glm::vec3 e2) {
        return std::vector<glm::dvec3>{glm::dvec3(p0), glm::dvec3(p0 + e1), glm::dvec3(p0 + e1 + e2), glm::dvec3(p0 + e2)};
    };
    const double small = polygon_irradiance(corners(small_p0, small_e1, small_e2), glm::dvec3(0.0), glm::dvec3(0, 1, 0), 10.0);
    const double truth = small + polygon_irradiance(corners(big_p0, big_e1, big_e2), glm::dvec3(0.0), glm::dvec3(0, 1, 0), 10.0);
    REQUIRE(small > 0.25 * truth);
    const glm::vec3 n(0, 1, 0), origin = offset_origin(glm::vec3(0.0f), n, render_ray_offset(g.info), true);
    const int estimates = 2000;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < estimates; ++i) {
        // albedo pi: the irradiance itself.
        const glm::vec3 e = direct_light_with(g, lights, origin, n, glm::vec3(3.14159265f), 16,
                                              ShadingRandom{static_cast<std::uint32_t>(i), 7u});
        sum += e.x;
        sum2 += static_cast<double>(e.x) * e.x;
    }
    const double mean = sum / estimates, spread = std::sqrt(std::max(0.0, sum2 / estimates - mean * mean));
    INFO("truth " << truth << ", mean " << mean << ", spread of a 16-ray estimate " << spread);
    CHECK(mean == Approx(truth).epsilon(0.03));
    CHECK(spread < 0.5 * truth);
}

TEST_CASE("the light frame a point's shadow rays share gives the samples a fresh set-up gives, bit for bit",
          "[render][lights]") {
    // Three rectangles: the choice of light changes from ray to ray, so the memo must set up anew
    // whenever it does.
    test::HandBuiltScene scene;
    scene.add_quad({-5, 0, -5}, {0, 0, 10}, {10, 0, 0}, scene.add_material(glm::vec3(0.5f)));
    scene.add_parallelogram_light({-1, 2, -1}, {2, 0, 0}, {0, 0, 1}, glm::vec3(4.0f));
    scene.add_parallelogram_light({0.5f, 0.3f, 0.2f}, {0.3f, 0, 0}, {0, 0, 0.2f}, glm::vec3(9.0f));
    scene.add_parallelogram_light({-1, 1, 1}, {0.5f, 0, 0}, {0, 0, 0.5f}, glm::vec3(6.0f));
    const SceneViews views = scene.views();
    const LightPowerTable power = light_power_table(views.geometry);
    const LightSelection lights = power.selection();
    REQUIRE(lights.count == 3);
    const glm::vec3 n(0, 1, 0);
    int changes = 0;
    for (int point = 0; point < 50; ++point) {
        const glm::vec3 origin(0.1f * point - 2.5f, 1e-3f, 0.05f * point - 1.0f);
        const ShadingRandom random{static_cast<std::uint32_t>(point), 7u};
        LightFrameMemo memo;
        std::uint32_t last = 0xffffffffu;
        for (std::uint32_t j = 0; j < 64; ++j) {
            Ray a, b;
            glm::vec3 ea(0.0f), eb(0.0f);
            const bool sa = light_sample(views.geometry, lights, origin, n, j, 8, random, a, ea, &memo);
            const bool sb = light_sample(views.geometry, lights, origin, n, j, 8, random, b, eb);
            REQUIRE(sa == sb);
            if (memo.light != last) ++changes, last = memo.light;
            if (!sa) continue;
            CHECK(std::memcmp(&a, &b, sizeof a) == 0);
            CHECK(std::memcmp(&ea, &eb, sizeof ea) == 0);
        }
    }
    CHECK(changes > 200);  // the lights did alternate
}
