// FilterMemo: decisions read back from the memo, or taken from its remembered vectors, are the
// surface filter's, whatever the sequence of normals, settings, maps and photons (slots shared
// by several photons included).
#include <catch2/catch.hpp>

#include <random>

#include "runtime/photons/filter_memo.h"
#include "runtime/photons/radiance_estimate.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/built_tree_view.h"

using namespace kdpm;

TEST_CASE("Decisions through a FilterMemo are the surface filter's", "[photons][memo]") {
    auto a = build_photon_tree(test::synthetic_photons(9000, 41).hits, PhotonTreeOptions{});
    auto b = build_photon_tree(test::synthetic_photons(9000, 43).hits, PhotonTreeOptions{});
    const PhotonMapView maps[] = {view_of(a), view_of(b)};
    const glm::vec3 normals[] = {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0.6f, 0.8f, 0.0f}, {0, -1, 0}};
    std::mt19937 rng(47);
    std::uniform_int_distribution<std::uint32_t> pick(0, 8999);
    static FilterMemo memo;
    std::uint64_t remembered = 0, vectors_reused = 0, asked = 0;
    const float cosines[] = {0.7f, -1.0f, 0.3f};
    int map_i = 0, normal_i = 0, cos_i = 0;
    std::uint32_t min_bounce = 0, exclude = 0;
    for (int query = 0; query < 400; ++query) {
        // Runs of 8 queries with the same inputs (read back), then one input changes.
        if (query > 0 && query % 8 == 0) {
            switch ((query / 8) % 5) {
                case 0: map_i ^= 1; break;
                case 1: normal_i = (normal_i + 1) % 5; break;
                case 2: cos_i = (cos_i + 1) % 3; break;
                case 3: min_bounce ^= 1; break;
                default: exclude ^= kPhotonCaustic; break;
            }
        }
        const PhotonMapView& map = maps[map_i];
        const glm::vec3 n = normals[normal_i];
        const float min_cos = cosines[cos_i];
        if (query % 50 == 49) memo.forget();
        if (query == 200) memo.generation = 0xffffffffu;  // the next generation wraps: the tags start over
        const SurfacePhotonFilter filter(map, n, min_cos, min_bounce, exclude);
        memo.use_for(map, n, min_cos, min_bounce, exclude);
        for (int i = 0; i < 300; ++i) {
            // Neighbouring photons, and photons that share a slot with them.
            std::uint32_t p = i < 200 ? (pick(rng) % 400) + 100 * (query % 8) : pick(rng);
            if (i % 7 == 0 && p + FilterMemo::kSlots < map.photon_count) p += FilterMemo::kSlots;
            const std::uint32_t slot = p & (FilterMemo::kSlots - 1);
            const bool decided = memo.tag[slot] == ((memo.generation << 32) | p);
            remembered += decided;
            vectors_reused += !decided && memo.vector_tag[slot] == ((memo.vector_generation << 32) | p);
            ++asked;
            INFO("query " << query << " photon " << p);
            REQUIRE(memo.decide(p, filter) == filter(p));
        }
    }
    CHECK(remembered > asked / 4);        // the memo did answer from memory
    CHECK(vectors_reused > asked / 50);   // and decided anew from remembered vectors
}
