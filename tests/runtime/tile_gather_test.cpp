// The CPU backend gathers photons by 8x8 tile with radius hints (PhotonTileGatherPass); the GPU
// runs one pixel per thread (PhotonGatherPass). Both must estimate the same radiance.
#include <catch2/catch.hpp>

#include <vector>

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/render/passes/photon_tile_gather_pass.h"
#include "runtime/render/passes/trace_pass.h"
#include "runtime/shading/ray_offset.h"
#include "tests/runtime/built_scene.h"
#include "tests/runtime/in_memory_photons.h"

using namespace kdpm;

TEST_CASE("The tile gather estimates what the per-pixel gather does", "[render][gather]") {
    // A size that is no multiple of 8: edge tiles are narrower and shorter.
    const std::uint32_t width = 61, height = 37;
    test::BuiltScene scene(3000, 5, width, height);
    const test::InMemoryPhotons photons(scene.views.geometry, 30000, 3, 32);
    const PhotonMaps maps = photons.maps();
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;

    std::vector<glm::vec3> emitted(pixels), per_pixel(pixels * kMaxDiffuseVertices),
        by_tile(pixels * kMaxDiffuseVertices), accum(pixels);
    std::vector<std::uint32_t> vertex_count(pixels);
    std::vector<DiffuseVertex> vertices(pixels * kMaxDiffuseVertices);
    FrameBuffersView fb;
    fb.width = width;
    fb.height = height;
    fb.emitted = emitted.data();
    fb.vertex_count = vertex_count.data();
    fb.vertices = vertices.data();
    fb.accum = accum.data();
    const PinholeCamera camera = PinholeCamera::from_record(scene.views.camera, width, height, 1);
    cpu_parallel_for(pixels, TracePass{scene.views.geometry, camera, fb, 0, 8,
                                       render_ray_offset(scene.views.geometry.info)});
    std::uint64_t diffuse = 0;
    for (std::uint32_t c : vertex_count) diffuse += c;
    REQUIRE(diffuse > pixels / 8);

    const int variant = GENERATE(0, 1, 2, 3, 4);
    RenderSettings settings;
    settings.k = variant == 3 ? 1 : variant == 4 ? 200 : 32;
    settings.cone_filter = variant == 1;
    settings.disc_flatten = variant == 2 ? 4.0f : 0.0f;
    const bool direct_light = variant == 1;  // the global map without direct hits, plus the caustic map
    INFO("variant " << variant);
    PhotonGatherPass gather = make_gather_pass(maps, direct_light, settings);

    gather.frame = fb;
    gather.frame.gathered = per_pixel.data();
    cpu_parallel_for(pixels, gather);
    gather.frame.gathered = by_tile.data();
    cpu_parallel_for(PhotonTileGatherPass::work_items(gather.frame), PhotonTileGatherPass{gather});

    float sum = 0.0f;
    for (std::uint64_t p = 0; p < pixels; ++p)
        for (std::uint32_t i = 0; i < vertex_count[p]; ++i) {
            const std::uint64_t slot = fb.vertex_slot(p, i);
            INFO("pixel " << p % width << "," << p / width << " vertex " << i);
            for (int c = 0; c < 3; ++c) REQUIRE(by_tile[slot][c] == Approx(per_pixel[slot][c]).epsilon(1e-5));
            sum += per_pixel[slot].x;
        }
    CHECK(sum > 0.0f);
}
