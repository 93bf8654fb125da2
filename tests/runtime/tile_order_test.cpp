// The tiled work order visits every pixel exactly once, for sizes that are and are not
// multiples of the tile size, and keeps a full tile's pixels together.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "runtime/render/tile_order.h"

using namespace kdpm;

TEST_CASE("tiled pixel order is a bijection for any image size", "[render][tiles]") {
    for (std::uint32_t w : {1u, 3u, 8u, 13u, 64u, 67u})
        for (std::uint32_t h : {1u, 5u, 8u, 17u, 40u}) {
            std::vector<int> seen(static_cast<std::size_t>(w) * h, 0);
            bool in_range = true;
            for (std::uint64_t i = 0; i < seen.size(); ++i) {
                const std::uint64_t p = tiled_pixel(i, w, h);
                if (p >= seen.size()) in_range = false;
                else ++seen[p];
            }
            INFO(w << "x" << h);
            CHECK(in_range);
            CHECK(std::count(seen.begin(), seen.end(), 1) == static_cast<long>(seen.size()));
        }
}

TEST_CASE("the first 64 work items cover the top-left 8x8 tile", "[render][tiles]") {
    for (std::uint64_t i = 0; i < 64; ++i) {
        const std::uint64_t p = tiled_pixel(i, 100, 50);
        CHECK(p % 100 < 8);
        CHECK(p / 100 < 8);
    }
}
