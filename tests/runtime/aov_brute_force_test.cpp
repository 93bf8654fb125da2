// The triangle and depth AOVs of a rendered image equal a brute-force cast of each pixel's
// camera ray over every triangle (no kd-tree).
#include <catch2/catch.hpp>

#include "runtime/geometry/scene_traversal.h"
#include "runtime/render/camera.h"
#include "runtime/render/renderer.h"
#include "tests/runtime/built_scene.h"

using namespace kdpm;

TEST_CASE("triangle and depth AOVs equal a brute-force cast over all triangles", "[render][aov]") {
    test::BuiltScene scene(1500, 7, 40, 30);
    Renderer renderer(scene.views, BackendKind::cpu);
    RenderSettings settings;
    settings.mode = RenderMode::direct;
    settings.light_samples = 1;
    settings.aovs.depth = settings.aovs.triangle = settings.aovs.normal = settings.aovs.position = true;
    RenderResult r = renderer.render(settings);
    REQUIRE(r.aovs.triangle.size() == 40u * 30u);

    const GeometryView& g = scene.views.geometry;
    PinholeCamera cam = PinholeCamera::from_record(scene.views.camera, 40, 30, 1);
    int hits = 0, mismatches = 0;
    for (std::uint32_t y = 0; y < 30; ++y)
        for (std::uint32_t x = 0; x < 40; ++x) {
            const std::size_t i = y * 40 + x;
            CameraRay c = cam.ray(x, y, 0);
            Hit h = closest_hit_brute_force(g, Ray{c.origin, 0.0f, c.direction, 1e30f});
            const std::int32_t expected = h.found() ? static_cast<std::int32_t>(g.triangles[h.triangle].source_index) : -1;
            hits += h.found();
            if (r.aovs.triangle[i] != expected) {
                ++mismatches;
                continue;
            }
            if (h.found()) {
                CHECK(r.aovs.depth[i] == Approx(h.t).epsilon(1e-5));
                glm::vec3 p = c.origin + h.t * c.direction;
                CHECK(r.aovs.position[i * 3 + 1] == Approx(p.y).margin(1e-4));
                CHECK(glm::dot(glm::vec3(r.aovs.normal[i * 3], r.aovs.normal[i * 3 + 1], r.aovs.normal[i * 3 + 2]),
                               c.direction) <= 0.0f);
            } else {
                CHECK(std::isinf(r.aovs.depth[i]));
            }
        }
    CHECK(hits > 200);  // the camera sees the soup
    CHECK(mismatches == 0);
}

TEST_CASE("one Renderer follows a changing camera from frame to frame", "[render][aov]") {
    test::BuiltScene scene(600, 11, 24, 16);
    Renderer renderer(scene.views, BackendKind::cpu);
    const GeometryView& g = scene.views.geometry;
    for (int frame = 0; frame < 3; ++frame) {
        CameraRecord camera = scene.views.camera;
        camera.eye[0] += 0.3f * static_cast<float>(frame);  // the viewer moves sideways
        camera.eye[1] -= 0.2f * static_cast<float>(frame);
        RenderSettings settings;
        settings.mode = RenderMode::direct;
        settings.light_samples = 1;
        settings.camera = camera;
        settings.aovs.triangle = true;
        RenderResult r = renderer.render(settings);
        PinholeCamera cam = PinholeCamera::from_record(camera, 24, 16, 1);
        int mismatches = 0;
        for (std::uint32_t i = 0; i < 24u * 16u; ++i) {
            CameraRay c = cam.ray(i % 24, i / 24, 0);
            Hit h = closest_hit_brute_force(g, Ray{c.origin, 0.0f, c.direction, 1e30f});
            const std::int32_t expected = h.found() ? static_cast<std::int32_t>(g.triangles[h.triangle].source_index) : -1;
            mismatches += r.aovs.triangle[i] != expected;
        }
        INFO("frame " << frame);
        CHECK(mismatches == 0);
    }
}
