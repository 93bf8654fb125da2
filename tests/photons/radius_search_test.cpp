#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "runtime/photons/radius_search.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/built_tree_view.h"

using namespace kdpm;

TEST_CASE("Fixed-radius search finds exactly the photons brute force finds", "[photons][radius]") {
    auto set = test::synthetic_photons(5000, 21);
    for (auto builder : {PhotonTreeBuilder::vvh, PhotonTreeBuilder::balanced}) {
        PhotonTreeOptions options;
        options.builder = builder;
        auto tree = build_photon_tree(set.hits, options);
        auto view = view_of(tree);
        std::mt19937 rng(5);
        std::uniform_real_distribution<float> u(-0.1f, 1.1f);
        for (float radius : {0.001f, 0.02f, 0.1f, 0.4f}) {
            for (int qi = 0; qi < 20; ++qi) {
                glm::vec3 q(u(rng), u(rng), u(rng));
                std::vector<std::uint32_t> got;
                radius_search(view, q, radius, [&](std::uint32_t p, float d2) {
                    float dx = tree.x[p] - q.x, dy = tree.y[p] - q.y, dz = tree.z[p] - q.z;
                    CHECK(d2 == dx * dx + dy * dy + dz * dz);
                    got.push_back(p);
                });
                std::vector<std::uint32_t> want;
                for (std::uint32_t p = 0; p < tree.x.size(); ++p) {
                    float dx = tree.x[p] - q.x, dy = tree.y[p] - q.y, dz = tree.z[p] - q.z;
                    if (dx * dx + dy * dy + dz * dz < radius * radius) want.push_back(p);
                }
                std::sort(got.begin(), got.end());
                INFO("radius " << radius << " query " << qi);
                REQUIRE(got == want);
            }
        }
    }
}
