// The furnace test: inside a closed box whose walls all emit Le and reflect with albedo rho,
// the radiance is the same everywhere, Le * (1 + rho + rho^2 + ...) = Le / (1 - rho) (truncated
// after the last photon bounce). The box is built with the geometry builder and the photons
// are shot and organised in-process with the photon libraries, then the photon modes render
// (final gathering with and without the precomputed irradiance).
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

#include "builders/geometry/geometry_file_builder.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/render/renderer.h"
#include "tests/runtime/in_memory_photons.h"

using namespace kdpm;

namespace {

void add_quad(Scene& s, glm::vec3 p0, glm::vec3 e1, glm::vec3 e2) {
    auto arr = [](glm::vec3 v, float (&out)[3]) { out[0] = v.x, out[1] = v.y, out[2] = v.z; };
    float a[3], b[3], c[3], d[3];
    arr(p0, a), arr(p0 + e1, b), arr(p0 + e1 + e2, c), arr(p0 + e2, d);
    // Both triangles keep the winding of (e1, e2), so they face along cross(e1, e2).
    s.triangles.push_back(make_triangle(a, b, c, 0, static_cast<std::uint32_t>(s.triangles.size())));
    s.triangles.push_back(make_triangle(a, c, d, 0, static_cast<std::uint32_t>(s.triangles.size())));
}

}  // namespace

TEST_CASE("a closed emitting diffuse box renders Le over one minus rho in every photon mode", "[render][furnace]") {
    const float le = 1.0f, rho = 0.5f;
    const std::uint32_t bounces = 12;
    Scene scene;
    MaterialRecord m{};
    for (int c = 0; c < 3; ++c) m.diffuse[c] = rho, m.emission[c] = le;
    scene.materials.push_back(m);
    // The unit cube with every face's front side inside.
    add_quad(scene, {0, 0, 0}, {0, 0, 1}, {1, 0, 0});  // floor, +y
    add_quad(scene, {0, 1, 0}, {1, 0, 0}, {0, 0, 1});  // ceiling, -y
    add_quad(scene, {0, 0, 0}, {0, 1, 0}, {0, 0, 1});  // x = 0, +x
    add_quad(scene, {1, 0, 0}, {0, 0, 1}, {0, 1, 0});  // x = 1, -x
    add_quad(scene, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});  // z = 0, +z
    add_quad(scene, {0, 0, 1}, {0, 1, 0}, {1, 0, 0});  // z = 1, -z
    add_emissive_triangle_lights(scene);
    REQUIRE(scene.lights.size() == 12);
    // From the centre, looking at the middle of the z = 1 wall (far from edges and corners).
    const float eye[3] = {0.5f, 0.5f, 0.5f}, at[3] = {0.5f, 0.5f, 1.0f}, up[3] = {0, 1, 0};
    for (int c = 0; c < 3; ++c) scene.camera.eye[c] = eye[c], scene.camera.lookat[c] = at[c], scene.camera.up[c] = up[c];
    scene.camera.vfov_degrees = 30;
    scene.camera.width = scene.camera.height = 12;
    scene.has_camera = true;

    GeometryBuild build = build_geometry_file(scene, KdBuildParams{});
    GeometryFile file = GeometryFile::from_bytes(build.writer.bytes(), "furnace.kdg");

    const test::InMemoryPhotons photons(file.view(), 200000, bounces, 200);
    SceneViews views;
    views.geometry = file.view();
    views.camera = file.camera();
    // Final gathering reads the irradiance precomputed at every 4th photon, or without it the
    // k-nearest estimate at each gather hit; one diffuse bounce more either way.
    views.photons = photons.maps(false);
    SceneViews with_irradiance = views;
    with_irradiance.photons = photons.maps(true);
    REQUIRE(with_irradiance.photons.irradiance.present());

    const double expected = le * (1.0 - std::pow(rho, bounces + 2)) / (1.0 - rho);
    const double expected_gather = le * (1.0 - std::pow(rho, bounces + 3)) / (1.0 - rho);
    Renderer renderer(views, BackendKind::cpu);
    Renderer gather_renderer(with_irradiance, BackendKind::cpu);
    for (RenderMode mode : {RenderMode::photons, RenderMode::direct_photons, RenderMode::final_gather}) {
      for (Renderer* which : {&renderer, &gather_renderer}) {
        if (which == &gather_renderer && mode != RenderMode::final_gather) continue;
        RenderSettings settings;
        settings.mode = mode;
        settings.k = 200;
        settings.light_samples = 16;
        settings.gather_rays = 16;
        RenderResult r = which->render(settings);
        double mean = 0;
        for (std::size_t i = 0; i < r.linear.pixel_count(); ++i) mean += r.linear.rgb[i * 3 + 1];
        mean /= static_cast<double>(r.linear.pixel_count());
        const double want = mode == RenderMode::final_gather ? expected_gather : expected;
        INFO("mode " << render_mode_name(mode) << (which == &gather_renderer ? " with" : " without")
                     << " precomputed irradiance: mean " << mean << ", expected " << want);
        CHECK(mean == Approx(want).epsilon(0.03));
      }
    }
}
