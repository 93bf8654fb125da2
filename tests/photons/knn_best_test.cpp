// The k best kept by a search (KnnBest): after any sequence of offers, the same distances as the
// k smallest of everything offered, the farthest in slot 0 and each index still beside its
// distance.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "runtime/photons/knn_best.h"
#include "runtime/photons/knn_search.h"

using namespace kdpm;

namespace {

// Offers n distances as knn_search does (strictly nearer than the current farthest once full)
// and checks the result against sorting all of them.
void check_offers(std::uint32_t k, std::uint32_t n, std::mt19937& rng, bool with_ties) {
    std::uniform_real_distribution<float> u(0.0f, 10.0f);
    std::vector<float> offered(n);
    for (float& d : offered) d = with_ties ? static_cast<float>(static_cast<int>(u(rng))) : u(rng);
    static KnnHeap heap;
    knn_detail::KnnBest best(heap, k);
    float limit = 3.402823466e38f;
    for (std::uint32_t p = 0; p < n; ++p) {
        if (!(offered[p] < limit)) continue;
        if (best.full()) {
            best.replace_farthest(offered[p], p);
            limit = best.farthest();
        } else if (best.append(offered[p], p)) {
            limit = best.farthest();
        }
        if (best.full()) {  // the farthest is the largest kept, at every step
            REQUIRE(best.farthest() == *std::max_element(heap.d2, heap.d2 + k));
        }
    }
    const std::uint32_t count = best.finish();
    std::vector<float> want = offered;
    std::sort(want.begin(), want.end());
    want.resize(std::min<std::size_t>(k, n));
    REQUIRE(count == want.size());
    std::vector<float> got(heap.d2, heap.d2 + count);
    if (count > 0) REQUIRE(heap.d2[0] == *std::max_element(got.begin(), got.end()));
    std::sort(got.begin(), got.end());
    REQUIRE(got == want);
    std::vector<std::uint32_t> seen;
    for (std::uint32_t i = 0; i < count; ++i) {
        REQUIRE(heap.index[i] < n);
        REQUIRE(offered[heap.index[i]] == heap.d2[i]);
        seen.push_back(heap.index[i]);
    }
    std::sort(seen.begin(), seen.end());
    REQUIRE(std::adjacent_find(seen.begin(), seen.end()) == seen.end());  // no photon twice
}

}  // namespace

TEST_CASE("KnnBest keeps the k smallest distances offered, the farthest in slot 0", "[photons][knn]") {
    std::mt19937 rng(5);
    for (std::uint32_t k : {1u, 2u, 3u, 7u, 8u, 9u, 17u, 31u, 32u, 33u, 64u, 100u, 255u, 256u}) {
        for (std::uint32_t n : {0u, 1u, k - 1, k, k + 1, 3 * k + 5, 1000u}) {
            INFO("k " << k << " offers " << n);
            check_offers(k, n, rng, false);
            check_offers(k, n, rng, true);
        }
    }
}

TEST_CASE("KnnBest's vector steps equal the portable loops CUDA runs", "[photons][knn]") {
    std::mt19937 rng(13);
    std::uniform_int_distribution<int> u(0, 6);
    for (int round = 0; round < 500; ++round) {
        const std::uint32_t n = 4u * static_cast<std::uint32_t>(1 + round % 8);
        float v[32];
        for (std::uint32_t i = 0; i < n; ++i) v[i] = static_cast<float>(u(rng)) - 1.0f;  // ties, and -1 padding
        const float m = knn_detail::max_of(v, n);
        INFO("round " << round << " n " << n);
        REQUIRE(m == knn_detail::portable::max_of(v, n));
        REQUIRE(m == *std::max_element(v, v + n));
        for (std::uint32_t i = 0; i < n; ++i)
            REQUIRE(knn_detail::first_equal(v, n, v[i]) == knn_detail::portable::first_equal(v, n, v[i]));
        REQUIRE(knn_detail::first_equal(v, n, m) == static_cast<std::uint32_t>(std::find(v, v + n, m) - v));
    }
}
