// Decoded photon vectors (unpack_directions, PhotonMapView::unpacked): the surface filter reads
// them instead of decoding, with every decision the same, and a radiance estimate is the same
// bit for bit, with and without a FilterMemo.
#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <vector>

#include "runtime/photons/filter_memo.h"
#include "runtime/photons/radiance_estimate.h"
#include "runtime/photons/unpacked_directions.h"
#include "tests/photons/decoded_photon_views.h"
#include "tests/photons/synthetic_photons.h"
#include "tests/support/built_tree_view.h"

using namespace kdpm;

using test::DecodedPhotonViews;

TEST_CASE("Decoded photon vectors are decode_octahedral's", "[photons][unpacked]") {
    auto tree = build_photon_tree(test::synthetic_photons(3000, 51).hits, PhotonTreeOptions{});
    const PhotonMapView map = view_of(tree);
    const std::vector<float> v = unpack_directions(map);
    REQUIRE(v.size() == 6u * map.photon_count);
    for (std::uint32_t p = 0; p < map.photon_count; ++p) {
        float d[3], n[3];
        decode_octahedral(map.directions[p].direction, d);
        decode_octahedral(map.directions[p].normal, n);
        const std::size_t count = map.photon_count;
        for (std::size_t c = 0; c < 3; ++c) {
            REQUIRE(std::memcmp(&d[c], &v[c * count + p], sizeof(float)) == 0);
            REQUIRE(std::memcmp(&n[c], &v[(3 + c) * count + p], sizeof(float)) == 0);
        }
    }
    PhotonMapView empty;
    CHECK(unpack_directions(empty).empty());
    CHECK(unpack_powers(empty).empty());
}

TEST_CASE("Decoded photon powers are photon_power's", "[photons][unpacked]") {
    auto tree = build_photon_tree(test::synthetic_photons(3000, 52).hits, PhotonTreeOptions{});
    const PhotonMapView map = view_of(tree);
    const std::vector<float> v = unpack_powers(map);
    REQUIRE(v.size() == 3u * map.photon_count);
    std::uint32_t bright = 0;
    for (std::uint32_t p = 0; p < map.photon_count; ++p) {
        const glm::vec3 want = photon_power(map.power[p]);
        REQUIRE(std::memcmp(&want.x, &v[3 * p], 3 * sizeof(float)) == 0);
        bright += want.x > 0.0f;
    }
    CHECK(bright > map.photon_count / 2);
}

TEST_CASE("The surface filter decides alike from decoded and from packed vectors", "[photons][unpacked]") {
    const DecodedPhotonViews views(9000, 53);
    const PhotonMapView &packed = views.packed, &unpacked = views.unpacked;
    // Unit normals (the quick path), a non-unit one (the exact path), and cosines for a direction
    // test only (-1), the quick margins (0.05..1) and below them (0.01).
    const glm::vec3 normals[] = {{0, 1, 0}, {0.6f, 0.8f, 0.0f}, {0, 0, -1}, {0.3f, 0.3f, 0.3f}};
    const float cosines[] = {-1.0f, 0.7f, 0.05f, 1.0f, 0.01f};
    std::uint64_t accepted = 0, asked = 0;
    static FilterMemo memo;
    for (const glm::vec3& n : normals)
        for (float c : cosines)
            for (std::uint32_t min_bounce : {0u, 1u}) {
                const SurfacePhotonFilter a(packed, n, c, min_bounce, 0), b(unpacked, n, c, min_bounce, 0);
                memo.use_for(unpacked, n, c, min_bounce, 0);
                for (std::uint32_t p = 0; p < packed.photon_count; p += 3) {
                    const bool want = a(p);
                    REQUIRE(b(p) == want);
                    REQUIRE(b.exact(p) == a.exact(p));
                    REQUIRE(memo.decide(p, b) == want);
                    accepted += want;
                    ++asked;
                }
            }
    CHECK(accepted > asked / 10);  // both verdicts occur
    CHECK(accepted < asked);
}

TEST_CASE("Sixteen decisions at once are the sixteen single ones", "[photons][unpacked]") {
    const DecodedPhotonViews views(5000, 61);
    const PhotonMapView &packed = views.packed, &unpacked = views.unpacked;
    const glm::vec3 normals[] = {{0, 1, 0}, {0.6f, 0.8f, 0.0f}, {0, 0, -1}, {0.3f, 0.3f, 0.3f}};
    std::uint64_t accepted = 0, asked = 0;
    for (const glm::vec3& n : normals)
        for (float c : {-1.0f, 0.7f, 0.01f})
            for (std::uint32_t min_bounce : {0u, 1u})
                for (std::uint32_t exclude : {0u, kPhotonCaustic}) {
                    const SurfacePhotonFilter single(packed, n, c, min_bounce, exclude),
                        batch(unpacked, n, c, min_bounce, exclude);
                    REQUIRE(batch.batched());
                    REQUIRE_FALSE(single.batched());
                    for (std::uint32_t base = 0; base + 16 <= packed.photon_count; base += 7) {
                        std::uint32_t want = 0;
                        for (std::uint32_t j = 0; j < 16; ++j) want |= static_cast<std::uint32_t>(single(base + j)) << j;
                        REQUIRE(batch.accepted16(base) == want);
                        accepted += static_cast<std::uint64_t>(__builtin_popcount(want));
                        asked += 16;
                    }
                }
    CHECK(accepted > asked / 10);
    CHECK(accepted < asked);
}

TEST_CASE("Radiance estimates from decoded vectors equal those from packed ones", "[photons][unpacked]") {
    const DecodedPhotonViews views(20000, 57);
    const PhotonMapView &packed = views.packed, &unpacked = views.unpacked;
    std::mt19937 rng(59);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    static KnnHeap heap;
    static FilterMemo memo_a, memo_b;
    std::uint32_t lit = 0;
    for (int q = 0; q < 400; ++q) {
        const glm::vec3 pos(u(rng), u(rng), u(rng));
        const glm::vec3 normal = q % 2 ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
        RadianceEstimateParams params;
        params.k = q % 3 == 0 ? 8 : 32;
        params.min_normal_cos = q % 5 == 0 ? -1.0f : 0.5f;
        params.cone_filter = q % 6 == 1;
        if (q % 7 == 3) {  // the fixed-radius estimate reads the powers too
            params.fixed_radius = true;
            params.max_radius = 0.05f;
        }
        const bool memo = q % 4 < 2;
        const RadianceEstimate a = estimate_radiance(packed, pos, normal, glm::vec3(0.5f), params, heap, 0.0f,
                                                     memo ? &memo_a : nullptr);
        const RadianceEstimate b = estimate_radiance(unpacked, pos, normal, glm::vec3(0.5f), params, heap, 0.0f,
                                                     memo ? &memo_b : nullptr);
        INFO("query " << q);
        test::require_same_estimate(a, b);
        lit += a.count > 0;
    }
    CHECK(lit > 200);
}
