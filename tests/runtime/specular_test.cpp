// Mirrors and glass: a mirror shows the emitter it reflects scaled by its reflectance; a glass
// pane's Fresnel split matches the closed form at normal incidence and conserves energy.
#include <catch2/catch.hpp>

#include "runtime/render/renderer.h"
#include "runtime/shading/specular.h"
#include "tests/runtime/hand_built_scene.h"

using namespace kdpm;

TEST_CASE("a mirror shows the reflected emitter scaled by its reflectance", "[render][specular]") {
    test::HandBuiltScene scene;
    const glm::vec3 le(2.0f, 1.0f, 0.5f), reflectance(0.9f, 0.5f, 0.25f);
    // A mirror in the plane z = 0 facing +z; an emitter in the plane x = 3 facing -x.
    const std::uint32_t mirror = scene.add_material(glm::vec3(0.0f), glm::vec3(0.0f), MaterialKind::mirror);
    for (int c = 0; c < 3; ++c) scene.materials[mirror].specular[c] = reflectance[c];
    scene.add_quad({-2, -2, 0}, {4, 0, 0}, {0, 4, 0}, mirror);
    scene.add_quad({3, -10, -10}, {0, 0, 20}, {0, 20, 0}, scene.add_material(glm::vec3(0.0f), le));
    // Looking at the mirror at 45 degrees: the reflected ray travels along +x to the emitter.
    scene.set_camera({-1, 0, 1}, {0, 0, 0}, {0, 1, 0}, 1.0f, 1, 1);
    SceneViews views = scene.views();
    Renderer renderer(views, BackendKind::cpu);
    RenderSettings settings;
    settings.mode = RenderMode::direct;
    RenderResult r = renderer.render(settings);
    for (int c = 0; c < 3; ++c) CHECK(r.linear.rgb[c] == Approx(reflectance[c] * le[c]));
}

TEST_CASE("Fresnel reflectance at normal incidence is ((n1 - n2) / (n1 + n2)) squared", "[specular]") {
    glm::vec3 refracted(0.0f);
    const glm::vec3 d(0, 0, -1), n(0, 0, 1);
    CHECK(fresnel_refract(d, n, 1.0f / 1.5f, refracted) == Approx(0.04f));
    CHECK(refracted.z == Approx(-1.0f));
    // Total internal reflection from inside at a grazing angle.
    const glm::vec3 grazing = glm::normalize(glm::vec3(1, 0, -0.2f));
    CHECK(fresnel_refract(grazing, n, 1.5f, refracted) == 1.0f);
    // Snell's law for an oblique ray.
    const glm::vec3 oblique = glm::normalize(glm::vec3(1, 0, -1));
    fresnel_refract(oblique, n, 1.0f / 1.5f, refracted);
    CHECK(refracted.x == Approx(std::sin(3.14159265f / 4) / 1.5f));
}

TEST_CASE("a glass pane in front of an emitter passes the light minus its Fresnel reflections", "[render][specular]") {
    test::HandBuiltScene scene;
    const std::uint32_t glass = scene.add_material(glm::vec3(0.0f), glm::vec3(0.0f), MaterialKind::glass);
    // Two parallel interfaces (a slab 0.1 thick): the front faces the camera, the back faces away.
    scene.add_quad({-5, -5, 0}, {10, 0, 0}, {0, 10, 0}, glass);
    scene.add_quad({-5, -5, -0.1f}, {0, 10, 0}, {10, 0, 0}, glass);
    scene.add_quad({-50, -50, -2}, {100, 0, 0}, {0, 100, 0}, scene.add_material(glm::vec3(0.0f), glm::vec3(1.0f)));
    scene.set_camera({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 1.0f, 1, 1);
    SceneViews views = scene.views();
    Renderer renderer(views, BackendKind::cpu);
    RenderSettings settings;
    settings.mode = RenderMode::direct;
    settings.max_depth = 16;
    RenderResult r = renderer.render(settings);
    // Straight through both interfaces: (1 - 0.04)^2, plus light bounced twice inside (tiny).
    CHECK(r.linear.rgb[0] == Approx(0.96f * 0.96f).epsilon(0.003));
}
