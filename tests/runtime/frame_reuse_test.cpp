// The CPU backend keeps a frame's arrays for the next (HostBlockCache): a frame must not see
// anything of the frames before it, whatever their sizes and modes.
#include <catch2/catch.hpp>

#include <cstring>

#include "runtime/backend/host_block_cache.h"
#include "runtime/render/renderer.h"
#include "tests/runtime/built_scene.h"
#include "tests/runtime/in_memory_photons.h"

using namespace kdpm;

TEST_CASE("the host block cache hands back what fits and frees what a frame left unused", "[render][memory]") {
    HostBlockCache cache;
    std::size_t big_capacity = 0, small_capacity = 0;
    void* big = cache.take(1 << 20, big_capacity);
    void* small = cache.take(1000, small_capacity);
    CHECK(big_capacity == (1u << 20));
    CHECK(reinterpret_cast<std::uintptr_t>(big) % 64 == 0);
    std::memset(big, 1, big_capacity);  // the memory is usable
    cache.give(big, big_capacity);
    cache.give(small, small_capacity);
    CHECK(cache.kept_bytes() == big_capacity + small_capacity);

    // The smallest block that fits, and none more than twice the size asked for.
    std::size_t c = 0;
    CHECK(cache.take(800, c) == small);
    CHECK(c == small_capacity);
    void* fresh = cache.take(400 << 10, c);  // the 1 MiB block is over twice as large
    CHECK(fresh != big);
    CHECK(c == (400u << 10));
    CHECK(cache.take(600 << 10, c) == big);
    cache.give(big, big_capacity);
    cache.give(fresh, 400 << 10);
    cache.give(small, small_capacity);

    // A trim keeps what was given back since the last trim; the next frees what was not taken.
    cache.trim();
    CHECK(cache.kept_bytes() == big_capacity + small_capacity + (400u << 10));
    CHECK(cache.take(1 << 20, c) == big);
    cache.give(big, c);
    cache.trim();
    CHECK(cache.kept_bytes() == big_capacity);
    cache.trim();
    CHECK(cache.kept_bytes() == 0);
}

TEST_CASE("CPU frames repeat exactly after frames of other sizes and modes", "[render][memory]") {
    test::BuiltScene scene(800, 3, 48, 32);
    const test::InMemoryPhotons photons(scene.views.geometry, 20000, 3, 32);
    scene.views.photons = photons.maps();
    const RenderMode mode = GENERATE(RenderMode::direct_photons, RenderMode::photons, RenderMode::final_gather,
                                     RenderMode::path, RenderMode::sppm);
    INFO("mode " << render_mode_name(mode));
    auto settings = [&](std::uint32_t w, std::uint32_t h) {
        RenderSettings s;
        s.mode = mode;
        s.width = w;
        s.height = h;
        s.spp = 2;
        s.light_samples = 4;
        s.gather_rays = 4;
        s.passes = 2;
        s.aovs.depth = s.aovs.normal = true;
        return s;
    };
    Renderer fresh(scene.views, BackendKind::cpu);
    const RenderResult expected = fresh.render(settings(48, 32));

    Renderer reused(scene.views, BackendKind::cpu);
    reused.render(settings(40, 24));  // smaller: its arrays are too small to serve
    RenderSettings other = settings(64, 48);
    other.mode = RenderMode::direct;  // another mode leaves other arrays and garbage behind
    reused.render(other);
    const RenderResult first = reused.render(settings(48, 32));
    const RenderResult second = reused.render(settings(48, 32));
    float sum = 0;
    for (float v : expected.linear.rgb) sum += v;
    CHECK(sum > 0.0f);
    CHECK(first.linear.rgb == expected.linear.rgb);
    CHECK(second.linear.rgb == expected.linear.rgb);
    CHECK(second.aovs.depth == expected.aovs.depth);
    CHECK(second.aovs.normal == expected.aovs.normal);
}
