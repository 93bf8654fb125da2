// The fixed-radius radiance estimate (kdpm-render --gather radius) against brute force: every
// photon within the radius that the surface filter accepts, box or cone weighted.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "runtime/photons/radiance_estimate.h"
#include "tests/support/built_tree_view.h"

using namespace kdpm;

TEST_CASE("Fixed-radius radiance estimate sums exactly the accepted photons in the disc", "[photons][radiance]") {
    // A floor (y = 0) lit from above, and under it the back of a thin wall lit from below (the
    // filter must drop those photons).
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<PhotonHit> hits;
    for (int i = 0; i < 20000; ++i) {
        PhotonHit h{};
        const bool below = i % 4 == 0;
        h.position[0] = u(rng), h.position[1] = below ? -0.001f : 0.0f, h.position[2] = u(rng);
        h.normal[1] = below ? -1.0f : 1.0f;
        h.direction[1] = below ? 1.0f : -1.0f;
        h.power[0] = 0.001f * (1.0f + u(rng)), h.power[1] = h.power[2] = 0.002f;
        h.flags = make_photon_flags(i % 3, false);
        hits.push_back(h);
    }
    const auto tree = build_photon_tree(hits, PhotonTreeOptions{});
    const auto view = view_of(tree);
    const glm::vec3 n(0.0f, 1.0f, 0.0f), albedo(0.5f, 0.25f, 1.0f);
    static KnnHeap heap;
    for (bool cone : {false, true})
        for (float r : {0.02f, 0.07f, 0.2f})
            for (glm::vec3 q : {glm::vec3(0.5f, 0.0f, 0.5f), glm::vec3(0.1f, 0.0f, 0.93f)}) {
                RadianceEstimateParams params;
                params.fixed_radius = true;
                params.max_radius = r;
                params.cone_filter = cone;
                const RadianceEstimate e = estimate_radiance(view, q, n, albedo, params, heap);
                double flux = 0.0;
                std::uint32_t count = 0;
                for (std::uint32_t p = 0; p < tree.info.photon_count; ++p) {
                    const float dx = tree.x[p] - q.x, dy = tree.y[p] - q.y, dz = tree.z[p] - q.z;
                    const float d2 = dx * dx + dy * dy + dz * dz;
                    if (!(d2 < r * r) || tree.y[p] < 0.0f) continue;  // outside, or the wall's back
                    const double w = cone ? std::max(0.0, 1.0 - std::sqrt(d2) / (1.1 * r)) : 1.0;
                    flux += w * photon_power(tree.power[p]).x;
                    ++count;
                }
                const double norm = cone ? 1.0 - 2.0 / (3.0 * 1.1) : 1.0;
                INFO("cone " << cone << ", r " << r << ", at " << q.x << ", " << q.z);
                CHECK(e.count == count);
                CHECK(e.radius == r);
                CHECK(e.radiance.x == Approx(0.5 / M_PI * flux / (M_PI * r * r * norm)).epsilon(1e-4));
            }
    RadianceEstimateParams none;
    none.fixed_radius = true;
    none.max_radius = 0.0f;  // no radius: nothing
    CHECK(estimate_radiance(view, glm::vec3(0.5f, 0.0f, 0.5f), n, albedo, none, heap).count == 0);
}
