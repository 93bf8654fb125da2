// The CPU backend's image does not depend on the number of threads: every work item writes only
// its own slots and every random number is a function of (pixel, sample, dimension).
#include <catch2/catch.hpp>

#include "runtime/backend/thread_limit.h"
#include "runtime/render/renderer.h"
#include "tests/runtime/built_scene.h"

using namespace kdpm;

TEST_CASE("CPU renders are identical with 1 and 2 threads", "[render][determinism]") {
    test::BuiltScene scene(800, 3, 48, 32);
    RenderSettings settings;
    settings.mode = GENERATE(RenderMode::direct, RenderMode::path, RenderMode::sppm);
    INFO("mode " << static_cast<int>(settings.mode));
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
