// --mode albedo: the first hit's reflectance, no light, on the CPU backend (the frame loop is
// the CUDA backend's too).
#include <catch2/catch.hpp>

#include "runtime/render/renderer.h"
#include "tests/runtime/hand_built_scene.h"

using namespace kdpm;

namespace {

RenderResult render_albedo(test::HandBuiltScene& scene, std::uint32_t spp) {
    SceneViews views = scene.views();
    Renderer renderer(views, BackendKind::cpu);
    RenderSettings settings;
    settings.mode = RenderMode::albedo;
    settings.spp = spp;
    return renderer.render(settings);
}

}  // namespace

TEST_CASE("albedo mode shows each material's reflectance, unlit, and black where rays leave", "[render][albedo]") {
    test::HandBuiltScene scene;
    const glm::vec3 albedo(0.2f, 0.4f, 0.6f), reflectance(0.9f, 0.5f, 0.25f);
    // A diffuse emitter: its emission must not show, only its albedo.
    const std::uint32_t wall = scene.add_material(albedo, glm::vec3(7.0f));
    const std::uint32_t mirror = scene.add_material(glm::vec3(0.0f), glm::vec3(0.0f), MaterialKind::mirror);
    for (int c = 0; c < 3; ++c) scene.materials[mirror].specular[c] = reflectance[c];
    scene.add_quad({-5, -5, 0}, {5, 0, 0}, {0, 10, 0}, wall);    // x < 0, faces +z
    scene.add_quad({0, -5, 0}, {5, 0, 0}, {0, 10, 0}, mirror);   // 0 < x < 5
    scene.add_parallelogram_light({-1, -1, 3}, {0, 2, 0}, {2, 0, 0}, glm::vec3(100.0f));
    scene.set_camera({0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 90.0f, 16, 8);  // sees past the quads' top and bottom
    const RenderResult r = render_albedo(scene, 4);
    const Image& img = r.linear;
    auto px = [&](int x, int y, int c) { return img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3 + c]; };
    for (int c = 0; c < 3; ++c) {
        CHECK(px(2, 4, c) == Approx(albedo[c]));
        CHECK(px(13, 4, c) == Approx(reflectance[c]));
    }
    // 90 degrees from 2 units away reaches y = +-2 at the quads: every pixel hits.
    for (std::size_t i = 0; i < img.pixel_count(); ++i) CHECK(img.rgb[i * 3] > 0.0f);

    scene.set_camera({0, 0, 20}, {0, 0, 0}, {0, 1, 0}, 60.0f, 16, 16);  // the quads fill the middle only
    const Image far = render_albedo(scene, 1).linear;
    CHECK(far.rgb[0] == 0.0f);  // the corner pixel misses
}
