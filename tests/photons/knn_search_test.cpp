#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "runtime/photons/knn_search.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/built_tree_view.h"

using namespace kdpm;

namespace {

// The k smallest squared distances (strictly inside max_radius when given), sorted.
std::vector<float> brute_force(const BuiltPhotonTree& t, glm::vec3 q, std::uint32_t k, float max_radius) {
    std::vector<float> d2;
    for (std::size_t p = 0; p < t.x.size(); ++p) {
        float dx = t.x[p] - q.x, dy = t.y[p] - q.y, dz = t.z[p] - q.z;
        float d = dx * dx + dy * dy + dz * dz;
        if (max_radius <= 0.0f || d < max_radius * max_radius) d2.push_back(d);
    }
    std::sort(d2.begin(), d2.end());
    if (d2.size() > k) d2.resize(k);
    return d2;
}

void check_knn_against_brute_force(PhotonTreeBuilder builder, std::uint32_t leaf_size, float max_radius) {
    auto set = test::synthetic_photons(6000, 7);
    PhotonTreeOptions options;
    options.builder = builder;
    options.leaf_size = leaf_size;
    auto tree = build_photon_tree(set.hits, options);
    auto view = view_of(tree);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-0.1f, 1.1f);
    static KnnHeap heap;
    for (std::uint32_t k : {1u, 2u, 3u, 8u, 17u, 32u, 64u, 100u, 255u, 256u}) {
        for (int qi = 0; qi < 25; ++qi) {
            glm::vec3 q(u(rng), u(rng), u(rng));
            if (qi % 3 == 0) q = {tree.x[qi * 31], tree.y[qi * 31], tree.z[qi * 31]};  // on a photon
            std::uint32_t n = knn_search(view, q, k, max_radius, heap);
            std::vector<float> got(heap.d2, heap.d2 + n);
            INFO("k " << k << " query " << qi);
            if (n > 0) REQUIRE(heap.d2[0] == *std::max_element(got.begin(), got.end()));  // the radius
            std::sort(got.begin(), got.end());
            REQUIRE(got == brute_force(tree, q, k, max_radius));
            for (std::uint32_t i = 0; i < n; ++i) {  // each index really is at its distance
                std::uint32_t p = heap.index[i];
                float dx = tree.x[p] - q.x, dy = tree.y[p] - q.y, dz = tree.z[p] - q.z;
                REQUIRE(dx * dx + dy * dy + dz * dz == heap.d2[i]);
            }
        }
    }
}

}  // namespace

TEST_CASE("kNN on the VVH tree equals brute force for k from 1 to 256", "[photons][knn]") {
    check_knn_against_brute_force(PhotonTreeBuilder::vvh, 8, 0.0f);
    check_knn_against_brute_force(PhotonTreeBuilder::vvh, 32, 0.0f);
}

TEST_CASE("kNN on the balanced tree equals brute force for k from 1 to 256", "[photons][knn]") {
    check_knn_against_brute_force(PhotonTreeBuilder::balanced, 1, 0.0f);
    check_knn_against_brute_force(PhotonTreeBuilder::balanced, 8, 0.0f);
}

TEST_CASE("kNN with a maximum radius keeps only photons inside it", "[photons][knn]") {
    check_knn_against_brute_force(PhotonTreeBuilder::vvh, 8, 0.05f);
    check_knn_against_brute_force(PhotonTreeBuilder::balanced, 4, 0.05f);
}

TEST_CASE("kNN on an empty map and on a single photon", "[photons][knn]") {
    static KnnHeap heap;
    auto empty = build_photon_tree({}, PhotonTreeOptions{});
    CHECK(knn_search(view_of(empty), glm::vec3(0.0f), 8, 0.0f, heap) == 0);
    PhotonMapView none;
    CHECK(knn_search(none, glm::vec3(0.0f), 8, 0.0f, heap) == 0);

    auto set = test::synthetic_photons(1, 3);
    auto one = build_photon_tree(set.hits, PhotonTreeOptions{});
    REQUIRE(knn_search(view_of(one), glm::vec3(2.0f), 8, 0.0f, heap) == 1);
    CHECK(heap.index[0] == 0);
}

TEST_CASE("kNN with the disc metric and a filter equals brute force under the same metric", "[photons][knn]") {
    auto set = test::synthetic_photons(6000, 17);
    auto tree = build_photon_tree(set.hits, PhotonTreeOptions{});
    auto view = view_of(tree);
    std::mt19937 rng(19);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    static KnnHeap heap;
    for (int qi = 0; qi < 60; ++qi) {
        glm::vec3 q(u(rng), u(rng), u(rng));
        glm::vec3 n = glm::normalize(glm::vec3(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f));
        DiscMetric metric{n, 8.0f};
        auto odd = [](std::uint32_t p) { return p % 2 == 1; };
        std::uint32_t k = 1 + qi * 4;
        std::uint32_t found = knn_search(view, q, k, 0.0f, metric, odd, heap);
        std::vector<float> got(heap.d2, heap.d2 + found), want;
        for (std::uint32_t p = 0; p < tree.x.size(); ++p)
            if (odd(p)) want.push_back(metric(tree.x[p] - q.x, tree.y[p] - q.y, tree.z[p] - q.z));
        std::sort(got.begin(), got.end());
        std::sort(want.begin(), want.end());
        want.resize(std::min<std::size_t>(want.size(), k));
        INFO("query " << qi << " k " << k);
        REQUIRE(got == want);
    }
}
