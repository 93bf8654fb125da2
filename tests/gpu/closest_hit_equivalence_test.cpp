// The same closest hits on both backends for random rays through the Cornell box and the Sponza:
// the CUDA build has no fused multiply-add (--fmad=false), and ray/triangle intersection and the
// kd-tree walk use only correctly rounded operations, so triangle, t, u and v agree bit for bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include "runtime/backend/cpu_device.h"
#include "tests/gpu/gpu_probes.h"
#include "tests/gpu/gpu_scenes.h"

using namespace kdpm;

namespace {

// Origins uniform in the scene's bounds (slightly enlarged), directions uniform on the sphere.
std::vector<Ray> random_rays(const GeometryInfo& info, std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    std::vector<Ray> rays(count);
    for (Ray& r : rays) {
        for (int a = 0; a < 3; ++a) {
            const float lo = info.bounds_min[a], hi = info.bounds_max[a], pad = 0.05f * (hi - lo);
            r.origin[a] = lo - pad + unit(rng) * (hi - lo + 2 * pad);
        }
        glm::vec3 d(gauss(rng), gauss(rng), gauss(rng));
        if (!(glm::dot(d, d) > 1e-12f)) d = glm::vec3(0, 1, 0);
        r.direction = d / std::sqrt(glm::dot(d, d));
        r.tmin = 0.0f;
        r.tmax = 3.402823466e38f;
    }
    return rays;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void check_same_hits(const std::string& name) {
    auto scene = test::build_gpu_test_scene(name, 0);
    const GeometryView& g = scene.views.geometry;
    const std::vector<Ray> rays = random_rays(g.info, 131072, 7);

    CpuDevice cpu;
    const std::vector<Hit> expected = test::run_closest_hits(cpu, g, rays);
    const std::vector<Hit> got = test::cuda_closest_hits(g, rays);
    REQUIRE(got.size() == expected.size());

    std::size_t hits = 0, different = 0, first_different = rays.size();
    for (std::size_t i = 0; i < rays.size(); ++i) {
        hits += expected[i].found();
        const bool same = got[i].triangle == expected[i].triangle &&
                          (!expected[i].found() || (same_bits(got[i].t, expected[i].t) &&
                                                    same_bits(got[i].u, expected[i].u) &&
                                                    same_bits(got[i].v, expected[i].v)));
        if (!same && different++ == 0) first_different = i;
    }
    INFO(name << ": " << rays.size() << " rays, " << hits << " hits on the CPU, " << different << " differ");
    if (first_different < rays.size())
        INFO("first differing ray " << first_different << ": CPU triangle " << expected[first_different].triangle
                                    << " t " << expected[first_different].t << ", CUDA triangle "
                                    << got[first_different].triangle << " t " << got[first_different].t);
    // The rays must exercise the tree: most of them hit something (the scenes are closed or nearly).
    CHECK(hits > rays.size() / 4);
    CHECK(different == 0);
}

}  // namespace

TEST_CASE("CUDA finds the same closest hits as the CPU on the Cornell box", "[gpu][trace]") {
    check_same_hits("cornell-box");
}

TEST_CASE("CUDA finds the same closest hits as the CPU on the Sponza", "[gpu][trace]") {
    if (!test::gpu_test_scene_available("sponza")) {
        WARN("the shared Sponza is not here (set KDPM_SCENES): skipped");
        return;
    }
    check_same_hits("sponza");
}
