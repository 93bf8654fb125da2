// Texture lookups of runtime/shading/texture_lookup.h against values worked out by hand: texel
// centres return the texel exactly, edges wrap, mip levels are box averages of the level below,
// and the trilinear level follows the footprint.
#include <catch2/catch.hpp>

#include <vector>

#include "builders/geometry/import/texture_mips.h"
#include "runtime/shading/texture_lookup.h"

using namespace kdpm;

namespace {

struct TestTexture {
    TextureRecord record{};
    std::vector<Texel> texels;

    TestTexture(std::uint32_t w, std::uint32_t h, std::vector<Texel> level0) {
        record.width = w;
        record.height = h;
        record.levels = texture_level_count(w, h);
        texels = build_mip_chain(std::move(level0), w, h);
        record.texel_count = texels.size();
    }
    glm::vec3 bilinear(std::uint32_t level, float u, float v) const {
        return bilinear_lookup(texels.data(), texture_level(record, level), glm::vec2(u, v));
    }
};

// Distinct values per texel: red = x + 10 y, green = 100 + x, blue = 200 + y.
std::vector<Texel> ramp(std::uint32_t w, std::uint32_t h) {
    std::vector<Texel> t(std::size_t{w} * h);
    for (std::uint32_t y = 0; y < h; ++y)
        for (std::uint32_t x = 0; x < w; ++x)
            t[y * w + x] = Texel{{static_cast<float>(x + 10 * y), 100.0f + x, 200.0f + y}};
    return t;
}

glm::vec3 vec(const Texel& t) { return glm::vec3(t.rgb[0], t.rgb[1], t.rgb[2]); }

}  // namespace

TEST_CASE("bilinear lookups at texel centres return the texel exactly", "[texture]") {
    const TestTexture tex(8, 4, ramp(8, 4));
    for (std::uint32_t y = 0; y < 4; ++y)
        for (std::uint32_t x = 0; x < 8; ++x) {
            const glm::vec3 got = tex.bilinear(0, (x + 0.5f) / 8.0f, (y + 0.5f) / 4.0f);
            CHECK(got == vec(tex.texels[y * 8 + x]));
            // Repeat addressing: one period over, or below zero, is the same texel.
            CHECK(tex.bilinear(0, (x + 0.5f) / 8.0f + 3.0f, (y + 0.5f) / 4.0f - 2.0f) == got);
        }
}

TEST_CASE("bilinear lookups between texel centres interpolate and wrap across edges", "[texture]") {
    const TestTexture tex(8, 4, ramp(8, 4));
    // Halfway between texels (2, 1) and (3, 1), a quarter of the way up to row 2.
    const glm::vec3 mid = tex.bilinear(0, 3.0f / 8.0f, (1.5f + 0.25f) / 4.0f);
    const glm::vec3 expected = 0.75f * (0.5f * vec(tex.texels[8 + 2]) + 0.5f * vec(tex.texels[8 + 3])) +
                               0.25f * (0.5f * vec(tex.texels[16 + 2]) + 0.5f * vec(tex.texels[16 + 3]));
    CHECK(mid.x == Approx(expected.x));
    CHECK(mid.y == Approx(expected.y));
    CHECK(mid.z == Approx(expected.z));
    // u = 0 lies halfway between the last column and the first.
    const glm::vec3 seam = tex.bilinear(0, 0.0f, 0.5f / 4.0f);
    CHECK(seam.y == Approx(0.5f * (100.0f + 7.0f) + 0.5f * 100.0f));
    const glm::vec3 corner = tex.bilinear(0, 0.0f, 0.0f);  // the four corner texels
    CHECK(corner.x == Approx(0.25f * (0 + 7 + 30 + 37)));
}

TEST_CASE("mip levels are box averages of the level below, down to 1 x 1", "[texture]") {
    const TestTexture tex(8, 4, ramp(8, 4));
    REQUIRE(tex.record.levels == 4);  // 8x4, 4x2, 2x1, 1x1
    REQUIRE(tex.texels.size() == 32u + 8 + 2 + 1);
    const Texel* level1 = tex.texels.data() + 32;
    for (std::uint32_t y = 0; y < 2; ++y)
        for (std::uint32_t x = 0; x < 4; ++x) {
            glm::vec3 sum(0.0f);
            for (std::uint32_t dy = 0; dy < 2; ++dy)
                for (std::uint32_t dx = 0; dx < 2; ++dx) sum += vec(tex.texels[(2 * y + dy) * 8 + 2 * x + dx]);
            CHECK(vec(level1[y * 4 + x]) == sum / 4.0f);
            // A lookup at the centre of a level-1 texel returns it exactly too.
            CHECK(tex.bilinear(1, (x + 0.5f) / 4.0f, (y + 0.5f) / 2.0f) == vec(level1[y * 4 + x]));
        }
    glm::vec3 mean(0.0f);
    for (std::uint32_t i = 0; i < 32; ++i) mean += vec(tex.texels[i]);
    const glm::vec3 top = vec(tex.texels.back());
    CHECK(top.x == Approx(mean.x / 32.0f));
    CHECK(top.y == Approx(mean.y / 32.0f));
    CHECK(top.z == Approx(mean.z / 32.0f));
}

TEST_CASE("odd sizes box-filter by covered area", "[texture]") {
    // 3 x 1 -> 1 x 1: each coarse texel covers 1.5 fine texels, so the middle one counts half.
    std::vector<Texel> row{Texel{{3, 0, 0}}, Texel{{6, 0, 0}}, Texel{{9, 0, 0}}};
    const std::vector<Texel> coarse = downsample_box(row, 3, 1);
    REQUIRE(coarse.size() == 1);
    CHECK(coarse[0].rgb[0] == Approx(6.0f));
    const std::vector<Texel> chain = build_mip_chain(ramp(5, 3), 5, 3);
    CHECK(chain.size() == 15u + 2 + 1);  // 5x3, 2x1, 1x1
}

TEST_CASE("trilinear lookups pick the level from the footprint", "[texture]") {
    const TestTexture tex(8, 4, ramp(8, 4));
    const glm::vec2 uv(0.3f, 0.6f);
    // Unknown or sub-texel footprints read level 0; one level-1 texel (2 level-0 texels) level 1.
    CHECK(texture_lookup(tex.texels.data(), tex.record, uv, 0.0f) == tex.bilinear(0, uv.x, uv.y));
    CHECK(texture_lookup(tex.texels.data(), tex.record, uv, 0.5f / 8.0f) == tex.bilinear(0, uv.x, uv.y));
    CHECK(texture_lookup(tex.texels.data(), tex.record, uv, 2.0f / 8.0f) == tex.bilinear(1, uv.x, uv.y));
    // Between levels 1 and 2 (footprint 2^1.5 texels): the mean of both, in log2 steps.
    const glm::vec3 between = texture_lookup(tex.texels.data(), tex.record, uv, 2.8284271f / 8.0f);
    const glm::vec3 expected = 0.5f * (tex.bilinear(1, uv.x, uv.y) + tex.bilinear(2, uv.x, uv.y));
    CHECK(between.x == Approx(expected.x).epsilon(1e-4));
    // Footprints past the texture read the 1 x 1 level; a NaN footprint is unknown: level 0.
    const glm::vec3 coarsest = texture_lookup(tex.texels.data(), tex.record, uv, 100.0f);
    CHECK(coarsest.x == Approx(tex.texels.back().rgb[0]));
    CHECK(coarsest.z == Approx(tex.texels.back().rgb[2]));
    CHECK(texture_lookup(tex.texels.data(), tex.record, uv, std::nanf("")) == tex.bilinear(0, uv.x, uv.y));
}
