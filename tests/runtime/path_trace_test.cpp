// The path-traced reference (--mode path) against closed forms and against the other modes:
// the furnace, a mirror and a glass slab in front of an emitter, the Cornell box with one
// bounce against direct light and with the photon map's bounce count against direct+photons.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>


#include "runtime/render/renderer.h"
#include "tests/runtime/built_scene.h"
#include "tests/runtime/cornell_box_runs.h"
#include "tests/runtime/hand_built_scene.h"
#include "tests/runtime/image_stats.h"
#include "tests/support/run_command.h"
#include "tests/support/temp_dir.h"

using namespace kdpm;
using kdpm::test::mean_of;
using kdpm::test::CornellBoxRuns;

namespace {

// The unit cube, every wall facing inside, emitting le and reflecting rho, each wall also a light.
struct FurnaceBox {
    test::HandBuiltScene scene;
    FurnaceBox(float le, float rho) {
        const std::uint32_t m = scene.add_material(glm::vec3(rho), glm::vec3(le));
        const glm::vec3 o(0.0f), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
        wall({0, 0, 0}, z, x, m, le);  // floor, +y
        wall({0, 1, 0}, x, z, m, le);  // ceiling, -y
        wall({0, 0, 0}, y, z, m, le);  // x = 0, +x
        wall({1, 0, 0}, z, y, m, le);  // x = 1, -x
        wall({0, 0, 0}, x, y, m, le);  // z = 0, +z
        wall({0, 0, 1}, y, x, m, le);  // z = 1, -z
        scene.set_camera({0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 1.0f}, {0, 1, 0}, 30.0f, 8, 8);
    }
    void wall(glm::vec3 p0, glm::vec3 e1, glm::vec3 e2, std::uint32_t m, float le) {
        scene.add_quad(p0, e1, e2, m);
        scene.add_parallelogram_light(p0, e1, e2, glm::vec3(le));
    }
};


}  // namespace

TEST_CASE("path tracing the furnace gives Le over one minus rho, and its truncation at N bounces",
          "[render][path][furnace]") {
    const float le = 1.0f, rho = 0.5f;
    FurnaceBox box(le, rho);
    SceneViews views = box.scene.views();
    Renderer renderer(views, BackendKind::cpu);
    RenderSettings settings;
    settings.mode = RenderMode::path;
    // Shadow rays to points near the wall corners have a heavy-tailed 1 / d^2: many samples.
    settings.spp = 4096;
    for (std::uint32_t bounces : {0u, 1u, 2u}) {
        settings.max_bounces = bounces;
        // Emission seen, then rho * le from each of the N diffuse vertices' shadow rays.
        const double expected = bounces == 0 ? le / (1.0 - rho) : le * (1.0 - std::pow(rho, bounces + 1)) / (1.0 - rho);
        const double mean = mean_of(renderer.render(settings).linear);
        INFO("max bounces " << bounces << ": mean " << mean << ", expected " << expected);
        CHECK(mean == Approx(expected).epsilon(0.02));
    }
}

TEST_CASE("path tracing a mirror and a glass slab matches their closed forms", "[render][path][specular]") {
    RenderSettings settings;
    settings.mode = RenderMode::path;
    settings.max_depth = 16;
    SECTION("a mirror shows the emitter behind the camera scaled by its reflectance") {
        test::HandBuiltScene scene;
        const glm::vec3 reflectance(0.9f, 0.5f, 0.25f);
        const std::uint32_t mirror = scene.add_material(glm::vec3(0.0f), glm::vec3(0.0f), MaterialKind::mirror);
        for (int c = 0; c < 3; ++c) scene.materials[mirror].specular[c] = reflectance[c];
        scene.add_quad({-5, -5, 0}, {0, 10, 0}, {10, 0, 0}, mirror);                                  // faces -z
        scene.add_quad({-50, -50, -3}, {100, 0, 0}, {0, 100, 0}, scene.add_material({0, 0, 0}, {1, 1, 1}));  // +z
        scene.set_camera({0, 0, -2}, {0, 0, 0}, {0, 1, 0}, 5.0f, 4, 4);
        SceneViews views = scene.views();
        Renderer renderer(views, BackendKind::cpu);
        RenderResult r = renderer.render(settings);
        for (std::size_t i = 0; i < r.linear.pixel_count(); ++i)
            for (int c = 0; c < 3; ++c) CHECK(r.linear.rgb[i * 3 + c] == Approx(reflectance[c]));
    }
    SECTION("a glass slab passes (1 - R) / (1 + R) of the emitter behind it, R the normal Fresnel reflectance") {
        test::HandBuiltScene scene;
        const std::uint32_t glass = scene.add_material(glm::vec3(0.0f), glm::vec3(0.0f), MaterialKind::glass);
        scene.add_quad({-5, -5, 0}, {10, 0, 0}, {0, 10, 0}, glass);
        scene.add_quad({-5, -5, -0.1f}, {0, 10, 0}, {10, 0, 0}, glass);
        scene.add_quad({-50, -50, -2}, {100, 0, 0}, {0, 100, 0}, scene.add_material(glm::vec3(0.0f), glm::vec3(1.0f)));
        scene.set_camera({0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 1.0f, 16, 16);
        SceneViews views = scene.views();
        Renderer renderer(views, BackendKind::cpu);
        settings.spp = 128;
        const double r = 0.04;  // ((1.5 - 1) / (1.5 + 1))^2
        // Every order of inter-reflection inside the slab: (1-R)^2 (1 + R^2 + R^4 + ...).
        const double expected = (1.0 - r) / (1.0 + r);
        const double mean = mean_of(renderer.render(settings).linear);
        INFO("mean " << mean << ", expected " << expected);
        CHECK(mean == Approx(expected).epsilon(0.01));
    }
}

TEST_CASE("the Cornell box path-traced agrees with direct light at one bounce and with direct+photons at the "
          "photon map's bounce count",
          "[render][path][cornell]") {
    CornellBoxRuns box;
    auto render = [&](const std::string& options, const std::string& name) { return box.render(options, name); };

    // One diffuse vertex: the same integral as --mode direct (emission seen, shadow rays).
    // Equal spp: the camera's jitter is a function of (pixel, sample) alone, so both modes see
    // the same camera rays and the bright emitter's antialiasing does not differ between them.
    const auto direct = render("--mode direct --spp 64 --light-samples 4", "direct");
    const auto one_bounce = render("--mode path --max-bounces 1 --spp 64", "path1");
    const double d = mean_of(direct), p1 = mean_of(one_bounce);
    INFO("direct " << d << ", path with one bounce " << p1);
    CHECK(p1 == Approx(d).epsilon(0.015));

    // The card's photon map has every bounce roulette leaves (up to 63), as the unlimited path
    // tracer; a map of bounces 0..4 holds the light of paths of 5 diffuse vertices.
    box.shoot_photons();
    const std::string kdp = box.build_photons("cb.kdp");
    const double dp = mean_of(box.render(box.kdg + " " + kdp, "--mode direct+photons --spp 64", "dp"));
    box.run("kdpm-shoot-photons " + box.kdg + " -n 200000 --bounces 4 -o " + (box.dir / "b4.kdph").string() + " --quiet");
    box.run("kdpm-build-photons " + (box.dir / "b4.kdph").string() + " -o " + (box.dir / "b4.kdp").string() + " --quiet");
    const double dp4 = mean_of(box.render(box.kdg + " " + (box.dir / "b4.kdp").string(), "--mode direct+photons --spp 64", "dp4"));
    const double p5 = mean_of(render("--mode path --max-bounces 5 --spp 64", "path5"));
    const double unlimited = mean_of(render("--mode path --spp 64", "path"));
    INFO("direct+photons " << dp << " (bounces 0..4: " << dp4 << "), path with 5 bounces " << p5 << ", unlimited "
                           << unlimited);
    CHECK(p5 == Approx(dp4).epsilon(0.03));
    CHECK(unlimited == Approx(dp).epsilon(0.03));
    // The indirect part alone (most of the image mean is the emitter seen directly).
    CHECK(p5 - p1 == Approx(dp4 - d).epsilon(0.05));
    CHECK(unlimited - p1 == Approx(dp - d).epsilon(0.05));
    CHECK(p5 > p1 * 1.2);              // indirect light is a large part of the box
    CHECK(unlimited >= p5 * 0.995);    // more bounces only add light
    CHECK(dp >= dp4 * 0.995);
}

TEST_CASE("final gathering on the Cornell box agrees with the path tracer at the photon map's bounce count, "
          "with the precomputed irradiance and without",
          "[render][final-gather][cornell]") {
    CornellBoxRuns box;
    box.shoot_photons();
    const std::string kdp = box.build_photons("cb.kdp");
    const std::string old_kdp = box.build_photons("old.kdp", " --irradiance-every 0");
    // A gather hit reads light of every bounce the card's photon map holds (up to 63, roulette
    // ends paths first), as the unlimited path tracer. Equal spp keeps the camera rays (and the
    // emitter's antialiasing) the same in every mode.
    const std::string options = "--mode final-gather --spp 16 --gather-rays 16";
    const double fg = mean_of(box.render(box.kdg + " " + kdp, options, "fg"));
    const double fallback = mean_of(box.render(box.kdg + " " + old_kdp, options, "fg-old"));
    const double direct = mean_of(box.render("--mode direct --spp 16", "direct"));
    const double p1 = mean_of(box.render("--mode path --max-bounces 1 --spp 16", "path1"));
    const double p6 = mean_of(box.render("--mode path --spp 16", "path"));
    INFO("final gather " << fg << " (without precomputed irradiance " << fallback << "), direct " << direct
                         << ", path with 1 and unlimited bounces " << p1 << ", " << p6);
    CHECK(fg == Approx(p6).epsilon(0.01));
    // The indirect part alone (most of the image mean is the emitter and direct light); measured
    // +1.2 % (the whole image +0.2 %), with the covered-share and plane tests at the gather hits.
    CHECK(fg - direct == Approx(p6 - p1).epsilon(0.03));
    // The precomputed lookup stands in for the k-nearest estimate it was made from; measured 0.08 %.
    CHECK(fallback == Approx(fg).epsilon(0.005));
    // The fallback is announced, once, unless --quiet.
    const std::string said = box.run("kdpm-render " + box.kdg + " " + old_kdp +
                                     " --mode final-gather --width 4 --height 4 --gather-rays 1 --backend cpu -o " +
                                     (box.dir / "small.exr").string());
    CHECK_THAT(said, Catch::Contains("no precomputed irradiance"));
    CHECK(said.find("no precomputed irradiance") == said.rfind("no precomputed irradiance"));
}

TEST_CASE("kdpm-render refuses a bad --max-bounces and names path among the modes", "[render][path][cli]") {
    test::TempDir dir;
    const std::string kdg = (dir / "cb.kdg").string();
    auto b = test::run_tool("kdpm-build-geometry " + test::source_path("scenes/cornell-box/cornell-box.json") +
                            " -o " + kdg + " --quiet");
    REQUIRE(b.exit_code == 0);
    auto negative = test::run_tool("kdpm-render " + kdg + " --mode path --max-bounces -1 -o " + (dir / "a.png").string());
    CHECK(negative.exit_code != 0);
    auto bogus = test::run_tool("kdpm-render " + kdg + " --mode paths -o " + (dir / "b.png").string());
    CHECK(bogus.exit_code != 0);
    CHECK(bogus.output.find("path") != std::string::npos);
}
