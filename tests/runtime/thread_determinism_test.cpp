// The CPU backend's image does not depend on the number of threads: every work item writes only
// its own slots and every random number is a function of (pixel, sample, dimension).
#include <catch2/catch.hpp>

#include "runtime/backend/thread_limit.h"
#include "runtime/render/renderer.h"
#include "tests/runtime/built_scene.h"
#include "tests/runtime/in_memory_photons.h"

using namespace kdpm;

TEST_CASE("CPU renders are identical with 1 and 2 threads", "[render][determinism]") {
    test::BuiltScene scene(800, 3, 48, 32);
    const test::InMemoryPhotons photons(scene.views.geometry, 20000, 3, 32);
    scene.views.photons = photons.maps();
    RenderSettings settings;
    // Final gathering with the irradiance cache (the default) and without it; the photon gather
    // (by tile on the CPU).
    const int variant = GENERATE(0, 1, 2, 3, 4, 5, 6);
    const RenderMode modes[] = {RenderMode::direct,       RenderMode::path,    RenderMode::sppm,
                                RenderMode::final_gather, RenderMode::final_gather, RenderMode::photons,
                                RenderMode::direct_photons};
    settings.mode = modes[variant];
    settings.irradiance_cache = variant != 4;
    settings.gather_rays = 4;
    INFO("mode " << static_cast<int>(settings.mode) << ", irradiance cache " << settings.irradiance_cache);
    settings.spp = 2;
    settings.light_samples = 4;
    settings.post.bloom = true;
    auto render_with = [&](int threads) {
        ThreadLimit limit(threads);
        Renderer renderer(scene.views, BackendKind::cpu);
        return renderer.render(settings);
    };
    RenderResult one = render_with(1), two = render_with(2);
    CHECK(one.linear.rgb == two.linear.rgb);
    CHECK(one.display.rgb == two.display.rgb);
    float sum = 0;
    for (float v : one.linear.rgb) sum += v;
    CHECK(sum > 0.0f);  // the light reaches the soup
}

TEST_CASE("a frame rendered into recycled images is the frame rendered into fresh ones", "[render][determinism]") {
    test::BuiltScene scene(800, 3, 48, 32);
    const test::InMemoryPhotons photons(scene.views.geometry, 20000, 3, 32);
    scene.views.photons = photons.maps();
    RenderSettings settings;
    settings.mode = GENERATE(RenderMode::photons, RenderMode::sppm);
    settings.spp = 1;
    settings.width = settings.height = 24;
    Renderer renderer(scene.views, BackendKind::cpu);
    const RenderResult fresh = renderer.render(settings);
    // The recycled storage held a brighter, larger frame: none of it may show through.
    RenderSettings larger = settings;
    larger.width = larger.height = 40;
    larger.post.exposure_stops = 3.0f;
    renderer.recycle(renderer.render(larger));
    const RenderResult reused = renderer.render(settings);
    CHECK(reused.linear.width == fresh.linear.width);
    CHECK(reused.linear.rgb == fresh.linear.rgb);
    CHECK(reused.exposed.rgb == fresh.exposed.rgb);
    CHECK(reused.display.rgb == fresh.display.rgb);
}
