#include <catch2/catch.hpp>

#include <random>

#include "runtime/photons/radiance_estimate.h"
#include "tests/support/built_tree_view.h"

using namespace kdpm;

namespace {

// Photons spread uniformly over the unit square of the floor (y = 0), each of power `each`,
// arriving from above; and a second sheet just below the floor lit from below (a leak).
std::vector<PhotonHit> lit_floor(std::uint32_t count, float each, bool with_leak) {
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<PhotonHit> hits;
    for (std::uint32_t i = 0; i < count; ++i) {
        PhotonHit h{};
        h.position[0] = u(rng), h.position[1] = 0.0f, h.position[2] = u(rng);
        h.normal[1] = 1.0f;
        h.direction[1] = -1.0f;
        h.power[0] = h.power[1] = h.power[2] = each;
        h.flags = make_photon_flags(i % 3, false);
        hits.push_back(h);
        if (with_leak) {  // the other side of a thin wall: normal down, arriving from below
            PhotonHit b = h;
            b.position[1] = -0.002f;
            b.normal[1] = -1.0f;
            b.direction[1] = 1.0f;
            b.power[0] = b.power[1] = b.power[2] = 10.0f * each;
            hits.push_back(b);
        }
    }
    return hits;
}

}  // namespace

TEST_CASE("Radiance estimate of a uniformly lit floor matches albedo E / pi", "[photons][radiance]") {
    const std::uint32_t count = 40000;
    const float each = 0.001f;  // irradiance E = count * each / 1 m^2 = 40 W/m^2
    const float albedo = 0.5f, expected = albedo * count * each / 3.14159265f;
    static KnnHeap heap;
    for (bool leak : {false, true}) {
        auto tree = build_photon_tree(lit_floor(count, each, leak), PhotonTreeOptions{});
        auto view = view_of(tree);
        for (bool cone : {false, true}) {
            RadianceEstimateParams params;
            params.k = 128;
            params.cone_filter = cone;
            double sum = 0.0;
            int n = 0;
            for (float x = 0.3f; x <= 0.7f; x += 0.1f)
                for (float z = 0.3f; z <= 0.7f; z += 0.1f) {
                    auto e = estimate_radiance(view, {x, 0.0f, z}, {0.0f, 1.0f, 0.0f}, glm::vec3(albedo), params, heap);
                    REQUIRE(e.count == params.k);
                    sum += e.radiance.x;
                    ++n;
                }
            INFO("leak sheet " << leak << " cone " << cone);
            CHECK(sum / n == Approx(expected).epsilon(0.05));
        }
    }
}

TEST_CASE("Radiance estimate honours min_bounce and the maximum radius", "[photons][radiance]") {
    const std::uint32_t count = 30000;
    auto tree = build_photon_tree(lit_floor(count, 0.001f, false), PhotonTreeOptions{});
    auto view = view_of(tree);
    static KnnHeap heap;
    RadianceEstimateParams all, indirect;
    all.k = indirect.k = 64;
    indirect.min_bounce = 1;  // two thirds of the photons have bounce >= 1
    auto a = estimate_radiance(view, {0.5f, 0.0f, 0.5f}, {0, 1, 0}, glm::vec3(1.0f), all, heap);
    auto b = estimate_radiance(view, {0.5f, 0.0f, 0.5f}, {0, 1, 0}, glm::vec3(1.0f), indirect, heap);
    CHECK(b.radiance.x == Approx(a.radiance.x * 2.0f / 3.0f).epsilon(0.25));

    RadianceEstimateParams limited;
    limited.k = 256;
    limited.max_radius = 0.01f;  // about pi 1e-4 * 30000 = 9 photons inside
    auto c = estimate_radiance(view, {0.5f, 0.0f, 0.5f}, {0, 1, 0}, glm::vec3(1.0f), limited, heap);
    CHECK(c.count < 30);
    CHECK(c.radius == Approx(0.01f));
    // Far from every photon: nothing found, no radiance.
    auto d = estimate_radiance(view, {5.0f, 5.0f, 5.0f}, {0, 1, 0}, glm::vec3(1.0f), limited, heap);
    CHECK(d.count == 0);
    CHECK(d.radiance.x == 0.0f);
}
