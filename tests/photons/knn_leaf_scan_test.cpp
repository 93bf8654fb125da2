// The CPU's leaf scan (distances of a leaf chunk first, then the photons in leaf order) and the
// surface filter's per-query margins: both must decide exactly as the plain scalar code does.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "runtime/photons/knn_search.h"
#include "runtime/photons/radiance_estimate.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/built_tree_view.h"

using namespace kdpm;

namespace {

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("leaf distances equal the scalar metric bit for bit, ties included", "[photons][knn]") {
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(-2.0f, 2.0f);
    for (std::uint32_t m = 0; m <= knn_detail::kLeafChunk; ++m) {
        std::vector<float> x(m), y(m), z(m);
        for (std::uint32_t j = 0; j < m; ++j) {
            x[j] = u(rng), y[j] = u(rng), z[j] = u(rng);
            if (j % 3 == 2) x[j] = x[j - 1], y[j] = y[j - 1], z[j] = z[j - 1];  // coincident photons
            if (j % 5 == 4) x[j] = -x[j], y[j] = -y[j], z[j] = -z[j];          // mirrored: equal distances from 0
        }
        const glm::vec3 q = m % 2 ? glm::vec3(0.0f) : glm::vec3(u(rng), u(rng), u(rng));
        const DiscMetric disc{glm::normalize(glm::vec3(u(rng), u(rng), u(rng))), 8.0f};
        float got[knn_detail::kLeafChunk], got_disc[knn_detail::kLeafChunk];
        knn_detail::leaf_distances(x.data(), y.data(), z.data(), m, q, EuclideanMetric{}, got);
        knn_detail::leaf_distances(x.data(), y.data(), z.data(), m, q, disc, got_disc);
        for (std::uint32_t j = 0; j < m; ++j) {
            INFO("m " << m << " photon " << j);
            CHECK(same_bits(got[j], EuclideanMetric{}(x[j] - q.x, y[j] - q.y, z[j] - q.z)));
            CHECK(same_bits(got_disc[j], disc(x[j] - q.x, y[j] - q.y, z[j] - q.z)));
        }
    }
}

// Leaves of many coincident photons span several chunks; a filter rejects some of them. The k
// found must be the k nearest accepted ones (as distances), each index accepted and distinct.
TEST_CASE("kNN over leaves longer than a chunk with coincident photons equals brute force", "[photons][knn]") {
    auto set = test::synthetic_photons(3000, 29);
    // Clusters of 40 photons at one point: one leaf each (coincident photons are never split).
    for (std::size_t c = 0; c < 8; ++c)
        for (int i = 0; i < 40; ++i) set.hits.push_back(set.hits[c * 300]);
    PhotonTreeOptions options;
    options.leaf_size = 48;
    auto tree = build_photon_tree(set.hits, options);
    auto view = view_of(tree);
    auto every_third_out = [](std::uint32_t p) { return p % 3 != 0; };
    std::mt19937 rng(31);
    static KnnHeap heap;
    for (int qi = 0; qi < 40; ++qi) {
        const std::uint32_t c = tree.x.size() > 0 ? static_cast<std::uint32_t>(rng() % tree.x.size()) : 0;
        const glm::vec3 q(tree.x[c] + 0.001f * (qi % 4), tree.y[c], tree.z[c]);
        const std::uint32_t k = 1 + (qi * 13) % 120;
        const std::uint32_t n = knn_search(view, q, k, 0.0f, EuclideanMetric{}, every_third_out, heap);
        std::vector<float> got(heap.d2, heap.d2 + n), want;
        for (std::uint32_t p = 0; p < tree.x.size(); ++p)
            if (every_third_out(p)) want.push_back(EuclideanMetric{}(tree.x[p] - q.x, tree.y[p] - q.y, tree.z[p] - q.z));
        std::sort(got.begin(), got.end());
        std::sort(want.begin(), want.end());
        want.resize(std::min<std::size_t>(want.size(), k));
        INFO("query " << qi << " k " << k);
        REQUIRE(got == want);
        std::vector<std::uint32_t> idx(heap.index, heap.index + n);
        for (std::uint32_t i = 0; i < n; ++i) {
            CHECK(every_third_out(heap.index[i]));
            const std::uint32_t p = heap.index[i];
            CHECK(EuclideanMetric{}(tree.x[p] - q.x, tree.y[p] - q.y, tree.z[p] - q.z) == heap.d2[i]);
        }
        std::sort(idx.begin(), idx.end());
        CHECK(std::adjacent_find(idx.begin(), idx.end()) == idx.end());
    }
}

// The filter's quick decisions (margins on unnormalised octahedral vectors, squared cosine
// margins computed once per query) against decoding every photon exactly.
TEST_CASE("the surface photon filter accepts exactly the photons exact decoding accepts", "[photons][radiance]") {
    std::mt19937 rng(37);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::uniform_int_distribution<std::uint32_t> bits;
    std::vector<PackedPhotonDirections> dirs;
    auto random_dir = [&] { return glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(1e-6f)); };
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 d = random_dir(), n = random_dir();
        dirs.push_back({encode_octahedral(d.x, d.y, d.z), encode_octahedral(n.x, n.y, n.z)});
    }
    for (int i = 0; i < 2000; ++i) dirs.push_back({bits(rng), bits(rng)});  // every packed value is decodable
    PhotonMapView map;
    map.directions = dirs.data();
    map.photon_count = static_cast<std::uint32_t>(dirs.size());
    std::size_t accepted = 0, rejected = 0;
    for (int qi = 0; qi < 24; ++qi) {
        glm::vec3 n = random_dir();
        if (qi % 6 == 0) n = glm::vec3(0.0f, 0.0f, 1.0f);
        const float min_cos = qi % 4 == 0 ? -1.0f : qi % 4 == 1 ? 0.05f : qi % 4 == 2 ? 0.7f : 0.999f;
        // Photons whose normal sits right at the threshold exercise the margins.
        for (int i = 0; i < 200; ++i) {
            const glm::vec3 t = glm::normalize(glm::cross(n, random_dir()));
            const float c = std::max(-1.0f, std::min(1.0f, min_cos + 1e-4f * u(rng)));
            const glm::vec3 m = c * n + std::sqrt(std::max(0.0f, 1.0f - c * c)) * t;
            const glm::vec3 d = -random_dir() * (u(rng) < 0 ? 1.0f : -1.0f);
            dirs.push_back({encode_octahedral(d.x, d.y, d.z), encode_octahedral(m.x, m.y, m.z)});
        }
        map.directions = dirs.data();
        map.photon_count = static_cast<std::uint32_t>(dirs.size());
        const SurfacePhotonFilter filter(map, n, min_cos, 0, 0);
        REQUIRE(filter.quick);
        for (std::uint32_t p = 0; p < map.photon_count; ++p) {
            INFO("query " << qi << " photon " << p);
            const bool want = filter.exact(p);
            REQUIRE(filter(p) == want);
            (want ? accepted : rejected) += 1;
        }
    }
    CHECK(accepted > 1000);
    CHECK(rejected > 1000);
}
