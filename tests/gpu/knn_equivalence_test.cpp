// The same k nearest photons on both backends, for every k from 1 to 256, on the Cornell box's
// photon map: the same count, distances and photon indices (the search is deterministic and its
// arithmetic correctly rounded, so the heaps agree entry for entry).
#include <catch2/catch.hpp>

#include <random>

#include "runtime/backend/cpu_device.h"
#include "tests/gpu/gpu_probes.h"
#include "tests/gpu/gpu_scenes.h"

using namespace kdpm;

TEST_CASE("CUDA finds the same k nearest photons as the CPU for k = 1..256", "[gpu][knn]") {
    auto scene = test::build_gpu_test_scene("cornell-box", 50000);
    const PhotonMapView& map = scene.views.photons.global;
    REQUIRE(map.photon_count > 10000);

    // Query points: half at photons (dense regions), half uniform in the scene's bounds.
    const GeometryInfo& info = scene.views.geometry.info;
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<glm::vec3> points(384);
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i % 2 == 0) {
            const std::uint32_t p = static_cast<std::uint32_t>(unit(rng) * (map.photon_count - 1));
            points[i] = glm::vec3(map.x[p], map.y[p] + 1e-3f, map.z[p]);
        } else {
            for (int a = 0; a < 3; ++a)
                points[i][a] = info.bounds_min[a] + unit(rng) * (info.bounds_max[a] - info.bounds_min[a]);
        }
    }

    CpuDevice cpu;
    std::size_t differing_k = 0;
    for (std::uint32_t k = 1; k <= kMaxGatherK; ++k) {
        const test::KnnResults expected = test::run_knn(cpu, map, points, k);
        const test::KnnResults got = test::cuda_knn(map, points, k);
        const bool same = got.found == expected.found && got.d2 == expected.d2 && got.index == expected.index;
        if (!same) {
            ++differing_k;
            INFO("k = " << k);
            CHECK(got.found == expected.found);
            CHECK(got.d2 == expected.d2);
            CHECK(got.index == expected.index);
        }
        // Every query finds min(k, photons) photons.
        for (std::uint32_t f : expected.found) REQUIRE(f == k);
    }
    CHECK(differing_k == 0);
}
