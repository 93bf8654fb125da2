// Radius hints (the CPU gather's tiles): the bound a neighbouring query gives, and estimates that
// start from a hint, whatever it is, equal estimates without one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>
#include <random>

#include "runtime/photons/radiance_estimate.h"
#include "runtime/photons/radius_hints.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/built_tree_view.h"

using namespace kdpm;

TEST_CASE("A query's k-th distance plus the distance to a nearby point bounds that point's", "[photons][hints]") {
    auto set = test::synthetic_photons(8000, 23);
    auto tree = build_photon_tree(set.hits, PhotonTreeOptions{});
    auto view = view_of(tree);
    std::mt19937 rng(29);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    static KnnHeap heap;
    auto kth = [&](glm::vec3 q, std::uint32_t k) {
        REQUIRE(knn_search(view, q, k, 0.0f, heap) == k);
        return std::sqrt(heap.d2[0]);
    };
    RadiusHints none;
    CHECK(none.hint(glm::vec3(0.5f)) == 0.0f);
    for (int i = 0; i < 200; ++i) {
        const std::uint32_t k = 1 + static_cast<std::uint32_t>(u(rng) * 100.0f);
        const glm::vec3 p(u(rng), u(rng), u(rng));
        const glm::vec3 q = p + 0.05f * glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
        RadiusHints hints;
        hints.remember(p, kth(p, k));
        INFO("query " << i << " k " << k);
        CHECK(hints.hint(q) >= kth(q, k) * (1.0f - 1e-6f));
    }
    // The smallest bound of those remembered; the oldest is forgotten after kRemembered more.
    RadiusHints hints;
    hints.remember(glm::vec3(0.0f), 0.5f);
    hints.remember(glm::vec3(1.0f, 0.0f, 0.0f), 0.1f);
    CHECK(hints.hint(glm::vec3(0.0f)) == 0.5f);
    CHECK(hints.hint(glm::vec3(0.9f, 0.0f, 0.0f)) == Approx(0.2f));
    for (std::uint32_t i = 0; i < RadiusHints::kRemembered - 1; ++i) hints.remember(glm::vec3(5.0f), 1.0f);
    CHECK(hints.hint(glm::vec3(0.0f)) == Approx(1.1f));  // (0,0,0) gone, (1,0,0) kept
    hints.remember(glm::vec3(5.0f), 1.0f);
    CHECK(hints.hint(glm::vec3(0.0f)) == Approx(1.0f + std::sqrt(75.0f)));
    // A full set (the CPU's four-wide path) gives the very float of a one-by-one minimum.
    RadiusHints full;
    for (std::uint32_t i = 0; i < RadiusHints::kRemembered; ++i)
        full.remember(glm::vec3(u(rng), u(rng), u(rng)), 0.2f * u(rng));
    for (int i = 0; i < 500; ++i) {
        const glm::vec3 q(u(rng), u(rng), u(rng));
        float least = 0.0f;
        for (std::uint32_t j = 0; j < RadiusHints::kRemembered; ++j) {
            const float dx = q.x - full.px[j], dy = q.y - full.py[j], dz = q.z - full.pz[j];
            const float bound = full.radius[j] + std::sqrt(dx * dx + dy * dy + dz * dz);
            least = j == 0 || bound < least ? bound : least;
        }
        REQUIRE(full.hint(q) == least);
    }
}

TEST_CASE("Radius hints come only from queries on the same surface", "[photons][hints]") {
    const glm::vec3 up(0.0f, 1.0f, 0.0f), side(1.0f, 0.0f, 0.0f);
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.1f, 1.0f, 0.0f));  // 5.7 degrees off up
    RadiusHints hints;
    hints.remember(glm::vec3(0.0f), side, 0.1f);
    CHECK(hints.hint(glm::vec3(0.0f), up) == 0.0f);  // the wall beside the floor gives none
    CHECK(hints.hint(glm::vec3(0.0f), tilted) == 0.0f);
    CHECK(hints.hint(glm::vec3(0.0f), side) == 0.1f);
    hints.remember(glm::vec3(1.0f, 0.0f, 0.0f), up, 0.5f);
    CHECK(hints.hint(glm::vec3(0.0f), up) == Approx(1.5f));  // the nearer wall query is passed over
    CHECK(hints.hint(glm::vec3(0.0f)) == 0.1f);  // an unfiltered search takes every bound
    RadiusHints unfiltered;
    unfiltered.remember(glm::vec3(0.0f), 0.1f);
    CHECK(unfiltered.hint(glm::vec3(0.0f), up) == 0.0f);  // no surface: no hint for a filtered search
    // A full set of mixed surfaces (the CPU's four-wide path) gives the float of a one-by-one
    // minimum over the queries whose normal is within kSameSurfaceCos.
    std::mt19937 rng(41);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int round = 0; round < 200; ++round) {
        RadiusHints full;
        const glm::vec3 normals[] = {up, side, tilted, glm::normalize(glm::vec3(0.01f, 1.0f, 0.0f))};
        for (std::uint32_t i = 0; i < RadiusHints::kRemembered; ++i)
            full.remember(glm::vec3(u(rng), u(rng), u(rng)), normals[rng() % 4], 0.2f * u(rng));
        const glm::vec3 q(u(rng), u(rng), u(rng));
        const glm::vec3 n = normals[rng() % 4];
        float least = 0.0f;
        for (std::uint32_t j = 0; j < RadiusHints::kRemembered; ++j) {
            if (n.x * full.nx[j] + n.y * full.ny[j] + n.z * full.nz[j] < RadiusHints::kSameSurfaceCos) continue;
            const float dx = q.x - full.px[j], dy = q.y - full.py[j], dz = q.z - full.pz[j];
            const float bound = full.radius[j] + std::sqrt(dx * dx + dy * dy + dz * dz);
            least = least == 0.0f || bound < least ? bound : least;
        }
        REQUIRE(full.hint(q, n) == least);
    }
}

TEST_CASE("An estimate started from any radius hint equals the estimate without one", "[photons][hints]") {
    auto set = test::synthetic_photons(20000, 31);
    auto tree = build_photon_tree(set.hits, PhotonTreeOptions{});
    auto view = view_of(tree);
    std::mt19937 rng(37);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    static KnnHeap heap;
    const glm::vec3 normals[] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    std::uint32_t retried = 0, checked = 0;
    for (int i = 0; i < 300; ++i) {
        RadianceEstimateParams params;
        params.k = 1 + static_cast<std::uint32_t>(u(rng) * 120.0f);
        params.cone_filter = i % 2 == 1;
        params.flatten = i % 3 == 0 ? 4.0f : 0.0f;
        params.max_radius = i % 4 == 0 ? 0.0f : 0.05f + 0.3f * u(rng);
        if (i % 5 == 0) {
            params.min_bounce = 1;
            params.exclude_flags = kPhotonCaustic;
        }
        const int kind = i % 3;  // on the floor, on the wall, or inside the cloud
        const glm::vec3 q = kind == 0 ? glm::vec3(u(rng), 0.0f, u(rng))
                                      : kind == 1 ? glm::vec3(0.0f, u(rng), u(rng)) : glm::vec3(u(rng), u(rng), u(rng));
        const glm::vec3 n = normals[kind == 0 ? 0 : kind == 1 ? 1 : 2];
        const RadianceEstimate want = estimate_radiance(view, q, n, glm::vec3(0.7f), params, heap);
        const float r = want.radius > 0.0f ? want.radius : 0.1f;
        // Too small (a second search), exactly the k-th distance (not strictly inside: too small),
        // just enough, loose, and beyond the search limit.
        for (float hint : {0.3f * r, r, 1.0001f * r, 1.5f * r, 50.0f * r}) {
            const RadianceEstimate got = estimate_radiance(view, q, n, glm::vec3(0.7f), params, heap, hint);
            INFO("query " << i << " k " << params.k << " max radius " << params.max_radius << " hint " << hint / r);
            REQUIRE(got.count == want.count);
            REQUIRE(got.radius == want.radius);
            for (int c = 0; c < 3; ++c) REQUIRE(got.radiance[c] == Approx(want.radiance[c]).epsilon(1e-5));
            retried += hint <= r && want.count == params.k;
            ++checked;
        }
    }
    CHECK(retried > 100);  // the second search did run
    CHECK(checked == 1500);
}

TEST_CASE("A k-nearest search from a hint finds the k nearest, retrying only when the hint holds fewer",
          "[photons][hints]") {
    auto set = test::synthetic_photons(6000, 41);
    auto tree = build_photon_tree(set.hits, PhotonTreeOptions{});
    auto view = view_of(tree);
    std::mt19937 rng(43);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    static KnnHeap heap;
    std::uint32_t retried = 0, first_try = 0;
    for (int i = 0; i < 200; ++i) {
        const std::uint32_t k = 1 + static_cast<std::uint32_t>(u(rng) * 60.0f);
        const glm::vec3 q(u(rng), u(rng), u(rng));
        // Brute force: the k-th smallest squared distance over every photon.
        std::vector<float> d2;
        for (std::uint32_t p = 0; p < view.photon_count; ++p) {
            const float dx = view.x[p] - q.x, dy = view.y[p] - q.y, dz = view.z[p] - q.z;
            d2.push_back(dx * dx + dy * dy + dz * dz);
        }
        std::nth_element(d2.begin(), d2.begin() + (k - 1), d2.end());
        const float want = d2[k - 1];
        for (float hint : {0.5f * std::sqrt(want), 1.01f * std::sqrt(want) + 1e-6f, 3.0f * std::sqrt(want)}) {
            int searches = 0;
            auto search = [&](float limit) {
                ++searches;
                return knn_search(view, q, k, limit, heap);
            };
            const std::uint32_t found = search_from_hint(search, k, hint, 0.0f);
            INFO("query " << i << " k " << k << " hint / k-th distance " << hint / std::sqrt(want));
            REQUIRE(found == k);
            CHECK(heap.d2[0] == want);
            (searches == 2 ? retried : first_try)++;
        }
    }
    CHECK(retried >= 200);   // every hint at half the k-th distance
    CHECK(first_try >= 400);  // every hint at or past it
}
