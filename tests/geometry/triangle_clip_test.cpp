// Clipping a triangle to both children of a split at once gives, bit for bit, what clipping it
// to each child cell gives: the builder's perfect splits must not depend on which is used.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "formats/triangle_clip.h"

using namespace kdpm;

namespace {

bool same_box(const AxisBox& a, const AxisBox& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Coordinates on a coarse grid half the time, so that vertices, cell walls and split planes
// often coincide (planar triangles, touching cells); otherwise anywhere in [-2, 2].
float coordinate(std::mt19937& rng) {
    std::uniform_real_distribution<float> any(-2.0f, 2.0f);
    std::uniform_int_distribution<int> grid(-4, 4);
    return rng() % 2 ? any(rng) : 0.5f * static_cast<float>(grid(rng));
}

}  // namespace

TEST_CASE("clipping to both children of a split equals clipping to each child", "[geometry][builder]") {
    std::mt19937 rng(7);
    std::size_t cut_both = 0;
    for (int trial = 0; trial < 200000; ++trial) {
        double v[3][3];
        for (auto& vertex : v)
            for (double& c : vertex) c = coordinate(rng);
        if (trial % 7 == 0) {  // flat on one axis
            const int a = static_cast<int>(rng() % 3);
            v[1][a] = v[2][a] = v[0][a];
        }
        AxisBox cell;
        for (int a = 0; a < 3; ++a) {
            const float x = coordinate(rng), y = coordinate(rng);
            cell.lo[a] = std::min(x, y);
            cell.hi[a] = std::max(x, y) + (x == y ? 0.5f : 0.0f);
        }
        const int axis = static_cast<int>(rng() % 3);
        const float t = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
        const float pos = rng() % 4 == 0 ? static_cast<float>(v[rng() % 3][axis])
                                         : cell.lo[axis] + t * (cell.hi[axis] - cell.lo[axis]);
        if (!(pos >= cell.lo[axis] && pos <= cell.hi[axis])) continue;
        AxisBox below_cell = cell, above_cell = cell;
        below_cell.hi[axis] = pos;
        above_cell.lo[axis] = pos;

        AxisBox below_alone{}, above_alone{}, below{}, above{};
        const bool meets_below_alone = clip_triangle_to_box(v, below_cell, below_alone);
        const bool meets_above_alone = clip_triangle_to_box(v, above_cell, above_alone);
        bool meets_below = false, meets_above = false;
        clip_triangle_to_children(v, cell, axis, pos, meets_below, below, meets_above, above);
        INFO("trial " << trial);
        REQUIRE(meets_below == meets_below_alone);
        REQUIRE(meets_above == meets_above_alone);
        if (meets_below) REQUIRE(same_box(below, below_alone));
        if (meets_above) REQUIRE(same_box(above, above_alone));
        cut_both += meets_below && meets_above;
    }
    CHECK(cut_both > 10000);  // the shared cuts ran often
}

TEST_CASE("the next float up and down are std::nextafter's", "[geometry][builder]") {
    const float inf = std::numeric_limits<float>::infinity();
    const float max = std::numeric_limits<float>::max(), tiny = std::numeric_limits<float>::denorm_min();
    std::vector<float> values = {0.0f, -0.0f, tiny, -tiny, 1.0f, -1.0f, max, -max, 1e-38f, -1e-38f};
    std::mt19937 rng(11);
    for (int i = 0; i < 100000; ++i) {
        std::uint32_t bits = static_cast<std::uint32_t>(rng());
        float f;
        std::memcpy(&f, &bits, sizeof f);
        if (std::isfinite(f)) values.push_back(f);
    }
    auto same = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    for (float f : values) {
        INFO("f = " << f);
        REQUIRE(same(float_below(f), std::nextafter(f, -inf)));
        REQUIRE(same(float_above(f), std::nextafter(f, inf)));
    }
    CHECK(same(float_below(inf), max));
    CHECK(same(float_above(-inf), -max));
}
