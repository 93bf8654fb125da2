// The furnace test: inside a closed box whose walls all emit Le and reflect with albedo rho,
// the radiance is the same everywhere, Le * (1 + rho + rho^2 + ...) = Le / (1 - rho) (truncated
// after the last photon bounce). The box is built with the geometry builder and the photons
// are shot and organised in-process with the photon libraries, then both lighting modes render.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

#include "tests/support/built_tree_view.h"
#include "builders/geometry/geometry_file_builder.h"
#include "builders/photons/photon_tree_builder.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/render/renderer.h"

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

TEST_CASE("a closed emitting diffuse box renders Le over one minus rho in both modes", "[render][furnace]") {
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

    ShootOptions shoot;
    shoot.photons = 200000;
    shoot.max_bounces = bounces;
    ShotPhotons shot = shoot_photons(file.view(), shoot);
    REQUIRE(!shot.hits.empty());
    BuiltPhotonTree global = build_photon_tree(shot.hits, PhotonTreeOptions{}, shot.info.emitted_count, bounces);
    std::vector<PhotonHit> caustic_hits;  // no specular surfaces: stays empty
    BuiltPhotonTree caustic = build_photon_tree(caustic_hits, PhotonTreeOptions{}, shot.info.emitted_count, bounces);

    SceneViews views;
    views.geometry = file.view();
    views.camera = file.camera();
    views.photons.global = view_of(global);
    views.photons.caustic = view_of(caustic);
    views.photons.present = true;

    const double expected = le * (1.0 - std::pow(rho, bounces + 2)) / (1.0 - rho);
    Renderer renderer(views, BackendKind::cpu);
    for (RenderMode mode : {RenderMode::photons, RenderMode::direct_photons}) {
        RenderSettings settings;
        settings.mode = mode;
        settings.k = 200;
        settings.light_samples = 16;
        RenderResult r = renderer.render(settings);
        double mean = 0;
        for (std::size_t i = 0; i < r.linear.pixel_count(); ++i) mean += r.linear.rgb[i * 3 + 1];
        mean /= static_cast<double>(r.linear.pixel_count());
        INFO("mode " << render_mode_name(mode) << ": mean " << mean << ", expected " << expected);
        CHECK(mean == Approx(expected).epsilon(0.03));
    }
}
