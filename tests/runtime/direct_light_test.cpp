// Direct light against the closed form: the irradiance at a point from a uniform polygonal
// emitter (Lambert's formula), times albedo / pi, is the radiance the renderer must return.
#include <catch2/catch.hpp>

#include <cmath>

#include "runtime/render/renderer.h"
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
