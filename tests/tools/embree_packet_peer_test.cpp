// kdpm-bench's Embree peer: rtcIntersect16 over 4x4 pixel tiles must report, per pixel, the hit
// that rtcIntersect1 reports for the same ray, edge tiles included (masked lanes write nothing).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "tools/bench/peer_embree.h"

using namespace kdpm::bench;

TEST_CASE("Embree 16-ray packets of 4x4 tiles hit what single rays hit", "[tools][bench][embree]") {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> pos(-1.0f, 1.0f), depth(2.0f, 6.0f), edge(-0.4f, 0.4f);
    std::vector<float> vertices;
    for (int t = 0; t < 300; ++t) {
        const float c[3] = {pos(rng), pos(rng), depth(rng)};
        for (int v = 0; v < 3; ++v)
            for (int a = 0; a < 3; ++a) vertices.push_back(c[a] + edge(rng));
    }
    EmbreePeer embree(vertices, 2);
    (void)embree.build_ms();

    // Widths and heights that are not multiples of 4 leave partial tiles on two sides.
    for (auto [width, height] : {std::pair<std::uint32_t, std::uint32_t>{18, 10}, {8, 8}, {5, 3}}) {
        std::vector<PeerRay> rays;
        for (std::uint32_t y = 0; y < height; ++y)
            for (std::uint32_t x = 0; x < width; ++x) {
                // A pinhole camera looking down +z whose wide field also sends some rays past every triangle.
                const float dx = (2.0f * (x + 0.5f) / width - 1.0f) * 0.8f;
                const float dy = (2.0f * (y + 0.5f) / height - 1.0f) * 0.8f;
                const float len = std::sqrt(dx * dx + dy * dy + 1.0f);
                rays.push_back({{0.0f, 0.0f, 0.0f}, {dx / len, dy / len, 1.0f / len}});
            }
        const PeerHit unset{-1.0f, 0x12345678u};
        std::vector<PeerHit> single(rays.size(), unset), packets(rays.size(), unset);
        embree.intersect(rays, single);
        embree.intersect16(rays, width, height, packets);
        std::size_t hits = 0;
        for (std::size_t i = 0; i < rays.size(); ++i) {
            INFO("size " << width << "x" << height << ", pixel " << i);
            REQUIRE(packets[i].triangle != unset.triangle);  // every pixel written
            CHECK(packets[i].triangle == single[i].triangle);
            if (single[i].triangle == 0xffffffffu) {
                CHECK(std::isinf(packets[i].t));
            } else {
                ++hits;
                CHECK(packets[i].t == Approx(single[i].t).epsilon(1e-5));
            }
        }
        CHECK(hits > 0);
        if (width == 18) CHECK(hits < rays.size());  // some misses too
    }
}
