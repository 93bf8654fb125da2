// The sppm photon grid's radius query against brute force: every photon within the radius is
// visited exactly once, none beyond it, whatever the radius is against the cell side.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "runtime/render/sppm/sppm_photon_grid.h"

using namespace kdpm;

namespace {

PhotonHit hit_at(float x, float y, float z, std::uint32_t bounce, float power) {
    PhotonHit h{};
    h.position[0] = x;
    h.position[1] = y;
    h.position[2] = z;
    h.flags = make_photon_flags(bounce, false);
    h.power[0] = h.power[1] = h.power[2] = power;
    h.normal[1] = 1.0f;
    return h;
}

}  // namespace

TEST_CASE("the sppm photon grid finds exactly the photons within a radius", "[render][sppm][grid]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<PhotonHit> hits;
    // Clustered and spread photons, a few of bounce 0 and 5 that the grid must leave out.
    for (int i = 0; i < 4000; ++i) {
        const float s = i % 3 == 0 ? 0.05f : 1.0f;
        hits.push_back(hit_at(s * u(rng), s * u(rng), s * u(rng), 1 + i % 3, static_cast<float>(i)));
    }
    for (int i = 0; i < 100; ++i) hits.push_back(hit_at(u(rng), u(rng), u(rng), i % 2 ? 0u : 5u, -1.0f));
    const float cell = GENERATE(0.01f, 0.1f, 0.3f);
    SppmPhotonGrid grid = build_sppm_photon_grid(hits, 1, 3, cell);
    REQUIRE(grid.view.photon_count == 4000u);
    grid.view.photons = grid.photons.data();
    grid.view.bucket_start = grid.bucket_start.data();
    int total_found = 0;
    for (int q = 0; q < 200; ++q) {
        const glm::vec3 x(1.2f * u(rng), 1.2f * u(rng), 1.2f * u(rng));
        const float r = q % 2 ? cell : 0.5f * (u(rng) + 1.0f) * 0.3f;  // at the cell side, or any up to 0.3
        std::vector<int> visits(hits.size(), 0);
        grid.view.for_each_within(x, r * r, [&](const SppmPhoton& p) {
            REQUIRE(p.power.x >= 0.0f);  // never a photon of another bounce
            ++visits[static_cast<std::size_t>(p.power.x)];
        });
        int wrong = 0, found = 0;
        for (std::size_t i = 0; i < 4000; ++i) {
            const glm::vec3 p(hits[i].position[0], hits[i].position[1], hits[i].position[2]);
            const glm::vec3 d = p - x;
            const int inside = d.x * d.x + d.y * d.y + d.z * d.z <= r * r ? 1 : 0;
            wrong += visits[i] != inside;
            found += inside;
        }
        INFO("query " << q << ", cell " << cell << ", radius " << r << ": " << found << " photons within");
        CHECK(wrong == 0);
        total_found += found;
    }
    CHECK(total_found > 1000);  // the queries do reach photons
}
