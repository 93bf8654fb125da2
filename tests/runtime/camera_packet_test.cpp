// The CPU backend traces camera rays in 4x4 packets and goes on with each pixel's trace pass
// from its packet's hit (PacketTracePass): the very same frame as the trace pass alone.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "runtime/backend/cpu_parallel_for.h"
#include "runtime/render/passes/packet_trace_pass.h"
#include "runtime/render/passes/trace_pass.h"
#include "runtime/shading/ray_offset.h"
#include "tests/runtime/built_scene.h"

using namespace kdpm;

namespace {

struct TracedFrame {
    std::vector<glm::vec3> emitted;
    std::vector<std::uint32_t> vertex_count;
    std::vector<DiffuseVertex> vertices;
    std::vector<float> depth;
};

TracedFrame trace(const test::BuiltScene& scene, const PinholeCamera& camera, std::uint32_t sample, bool packets) {
    const std::uint64_t pixels = static_cast<std::uint64_t>(camera.width) * camera.height;
    TracedFrame f{std::vector<glm::vec3>(pixels), std::vector<std::uint32_t>(pixels),
                  std::vector<DiffuseVertex>(pixels * kMaxDiffuseVertices), std::vector<float>(pixels)};
    std::vector<glm::vec3> accum(pixels);
    FrameBuffersView fb;
    fb.width = camera.width;
    fb.height = camera.height;
    fb.emitted = f.emitted.data();
    fb.vertex_count = f.vertex_count.data();
    fb.vertices = f.vertices.data();
    fb.accum = accum.data();
    fb.depth = f.depth.data();
    TracePass pass{scene.views.geometry, camera, fb, sample, 8, render_ray_offset(scene.views.geometry.info)};
    if (packets)
        cpu_parallel_for(PacketTracePass::work_items(camera.width, camera.height), PacketTracePass{pass});
    else
        cpu_parallel_for(pixels, pass);
    return f;
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

}  // namespace

TEST_CASE("Camera rays traced in packets leave the trace pass's frame unchanged", "[render][packets]") {
    // No multiple of 4: the edge blocks are partial packets. One sample per pixel (the pass
    // makes the pixel-centre rays of full blocks four at a time), and two: the second jitters.
    const std::uint32_t width = 61, height = 37;
    test::BuiltScene scene(3000, 5, width, height);
    const std::uint32_t samples = GENERATE(1u, 2u);
    const PinholeCamera camera = PinholeCamera::from_record(scene.views.camera, width, height, samples);
    for (std::uint32_t sample = 0; sample < samples; ++sample) {
        INFO(samples << " samples, sample " << sample);
        const TracedFrame single = trace(scene, camera, sample, false);
        const TracedFrame packed = trace(scene, camera, sample, true);
        std::uint64_t vertices = 0;
        for (std::uint32_t c : single.vertex_count) vertices += c;
        REQUIRE(vertices > width * height / 8);  // the soup fills a good part of the view
        CHECK(same_bytes(single.vertex_count, packed.vertex_count));
        CHECK(same_bytes(single.emitted, packed.emitted));
        CHECK(same_bytes(single.depth, packed.depth));
        CHECK(same_bytes(single.vertices, packed.vertices));  // slots past a pixel's count stay zero in both
    }
}
