// The irradiance cache at a crease: a low dark step on the lit floor of an open room. Within a
// few centimetres of the step's foot the step fills much of the floor's hemisphere, so the
// floor's indirect light there is far below what records a little further out see; a record
// valid that far (its radius set by the room, not by the step) must not be read at the foot.
// The cached image is compared with the uncached one (every point gathers) band by band.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/render/renderer.h"
#include "tests/runtime/hand_built_scene.h"
#include "tests/runtime/in_memory_photons.h"

using namespace kdpm;

namespace {

constexpr float kStepHeight = 0.12f, kStepFront = 0.3f, kStepHalfWidth = 0.5f;

struct StepRoom {
    test::HandBuiltScene scene;
    SceneViews views;

    StepRoom() {
        const std::uint32_t white = scene.add_material(glm::vec3(0.7f));
        const std::uint32_t dark = scene.add_material(glm::vec3(0.05f));
        scene.add_quad({-2, 0, 2}, {4, 0, 0}, {0, 0, -4}, white);  // floor, facing up
        scene.add_quad({-2, 0, -2}, {4, 0, 0}, {0, 2, 0}, white);  // back wall, facing +z
        scene.add_quad({2, 0, 2}, {-4, 0, 0}, {0, 2, 0}, white);   // front wall, facing -z
        scene.add_quad({-2, 0, 2}, {0, 0, -4}, {0, 2, 0}, white);  // left wall, facing +x
        scene.add_quad({2, 0, -2}, {0, 0, 4}, {0, 2, 0}, white);   // right wall, facing -x
        // The step: a box on the floor, its front face at z = kStepFront facing +z.
        const float h = kStepHeight, w = kStepHalfWidth, f = kStepFront;
        scene.add_quad({-w, h, f}, {2 * w, 0, 0}, {0, 0, -2 * f}, dark);  // top
        scene.add_quad({-w, 0, f}, {2 * w, 0, 0}, {0, h, 0}, dark);       // front
        scene.add_quad({w, 0, -f}, {-2 * w, 0, 0}, {0, h, 0}, dark);      // back
        scene.add_quad({-w, 0, -f}, {0, 0, 2 * f}, {0, h, 0}, dark);      // left
        scene.add_quad({w, 0, f}, {0, 0, -2 * f}, {0, h, 0}, dark);       // right
        scene.add_parallelogram_light({-0.8f, 1.9f, -0.8f}, {1.6f, 0, 0}, {0, 0, 1.6f}, glm::vec3(4.0f));
        scene.set_camera({0, 0.7f, 1.3f}, {0, 0.0f, 0.45f}, {0, 1, 0}, 40.0f, 128, 128);
        views = scene.views();
    }
};

struct Band {
    double sum = 0;
    int pixels = 0;
    double mean() const { return pixels ? sum / pixels : 0.0; }
};

// Mean green radiance of the floor pixels whose first hit lies at a distance from the step's
// front face in [near, far), and beside no other face.
Band floor_band(const RenderResult& r, float near, float far) {
    Band b;
    const std::size_t pixels = r.linear.rgb.size() / 3;
    for (std::size_t p = 0; p < pixels; ++p) {
        const glm::vec3 pos(r.aovs.position[3 * p], r.aovs.position[3 * p + 1], r.aovs.position[3 * p + 2]);
        const glm::vec3 n(r.aovs.normal[3 * p], r.aovs.normal[3 * p + 1], r.aovs.normal[3 * p + 2]);
        if (!(n.y > 0.99f) || std::fabs(pos.y) > 1e-3f || std::fabs(pos.x) > kStepHalfWidth - 0.1f) continue;
        const float d = pos.z - kStepFront;
        if (d < near || d >= far) continue;
        b.sum += r.linear.rgb[3 * p + 1];
        ++b.pixels;
    }
    return b;
}

// Indirect light only: the final gather's radiance less the direct light of the same pixels.
double indirect(const RenderResult& gathered, const RenderResult& direct, float near, float far) {
    return floor_band(gathered, near, far).mean() - floor_band(direct, near, far).mean();
}

}  // namespace

TEST_CASE("cache records out on the floor are not read at the foot of a step", "[render][final-gather][irradiance-cache]") {
    StepRoom room;
    const test::InMemoryPhotons photons(room.views.geometry, 200000, 4, 64);
    room.views.photons = photons.maps();
    RenderSettings settings;
    settings.mode = RenderMode::final_gather;
    settings.gather_rays = 64;
    settings.light_samples = 4;
    settings.spp = 8;
    settings.aovs.position = settings.aovs.normal = true;
    Renderer renderer(room.views, BackendKind::cpu);
    const RenderResult cached = renderer.render(settings);
    settings.irradiance_cache = false;
    const RenderResult uncached = renderer.render(settings);
    settings.mode = RenderMode::direct;
    settings.light_samples = 64;
    const RenderResult direct = renderer.render(settings);
    REQUIRE(floor_band(cached, 0.0f, 0.02f).pixels > 100);

    // The scene tests what it claims: at the foot the floor gets far less indirect light than
    // 16-34 cm out.
    const double foot = indirect(uncached, direct, 0.0f, 0.02f), out = indirect(uncached, direct, 0.16f, 0.34f);
    INFO("uncached indirect: at the foot " << foot << ", 16-34 cm out " << out);
    REQUIRE(foot > 0.0);
    REQUIRE(foot < 0.8 * out);
    // Observed: cached / uncached indirect 1.00, 1.00, 0.98, 1.00 from the foot out; with the
    // harmonic-mean radii and the looser in-front test of before, 1.31, 1.23, 1.17, 1.10 (the
    // step's top and the open floor lit its foot).
    for (float near : {0.0f, 0.02f, 0.04f, 0.08f}) {
        const float far = 2 * near + 0.02f;
        INFO("band " << near << ".." << far << " m from the step");
        CHECK(indirect(cached, direct, near, far) == Approx(indirect(uncached, direct, near, far)).epsilon(0.08));
    }
    // As many records as there are points would be no cache.
    CHECK(cached.times.cache_records * 16 < cached.times.cache_points);
}
