// The automatic depth limits: small nodes (at most kSmallLeafTriangles triangles, or
// kFastSmallLeafTriangles in a fast build) stop splitting at the small-node depth, larger ones
// go on to the full limit (a dense object far down a large, mostly empty scene keeps small
// leaves), and an explicit max_depth is a plain limit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "builders/geometry/sah/sah_kd_builder.h"
#include "tests/geometry/geometry_check.h"
#include "tests/geometry/random_scenes.h"

using namespace kdpm;

namespace {

// A finely tessellated ball of radius 1 standing on the floor of a hall a thousand times larger
// (the "teapot in a stadium"): its nodes lie deep below the cuts that isolate it.
std::vector<TriangleRecord> ball_in_a_hall() {
    constexpr int kAround = 96, kUp = 48;
    std::vector<TriangleRecord> tris;
    auto at = [](int i, int j, float (&p)[3]) {
        const float phi = 6.2831853f * static_cast<float>(i % kAround) / kAround;
        const float theta = 3.1415927f * static_cast<float>(j) / kUp;
        p[0] = std::sin(theta) * std::cos(phi);
        p[1] = 1.0f + std::cos(theta);
        p[2] = std::sin(theta) * std::sin(phi);
    };
    for (int j = 0; j < kUp; ++j)
        for (int i = 0; i < kAround; ++i) {
            float a[3], b[3], c[3], d[3];
            at(i, j, a), at(i + 1, j, b), at(i, j + 1, c), at(i + 1, j + 1, d);
            const auto id = static_cast<std::uint32_t>(tris.size());
            if (j > 0) tris.push_back(make_triangle(a, c, b, 0, id));
            if (j + 1 < kUp) tris.push_back(make_triangle(b, c, d, 0, id + 1));
        }
    const auto id = static_cast<std::uint32_t>(tris.size());
    float a[3] = {-1000, 0, -1000}, b[3] = {1000, 0, -1000}, c[3] = {1000, 0, 1000}, d[3] = {-1000, 0, 1000};
    tris.push_back(make_triangle(a, b, c, 0, id));
    tris.push_back(make_triangle(a, c, d, 0, id + 1));
    float e[3] = {-1000, 0, -1000}, f[3] = {1000, 0, -1000}, g[3] = {1000, 300, -1000};
    tris.push_back(make_triangle(e, f, g, 0, id + 2));
    return tris;
}

struct NodeFacts {
    std::uint32_t depth;
    std::size_t triangles;  // distinct triangles in the leaves below
};

// Depth and distinct triangle count of every inner node.
void inner_nodes(const KdTree& tree, std::uint32_t node, std::uint32_t depth, std::vector<NodeFacts>& out,
                 std::set<std::uint32_t>& below) {
    const KdNode n = tree.nodes[node];
    if (n.is_leaf()) {
        for (std::uint32_t i = 0; i < n.count(); ++i) below.insert(tree.leaf_indices[n.first() + i]);
        return;
    }
    std::set<std::uint32_t> mine;
    inner_nodes(tree, node + 1, depth + 1, out, mine);
    inner_nodes(tree, n.above_child(), depth + 1, out, mine);
    out.push_back({depth, mine.size()});
    below.insert(mine.begin(), mine.end());
}

std::vector<NodeFacts> inner_nodes(const KdTree& tree) {
    std::vector<NodeFacts> out;
    std::set<std::uint32_t> all;
    inner_nodes(tree, 0, 0, out, all);
    return out;
}

}  // namespace

// The automatic limits for the Sponza's 66,454 triangles: nodes of more than `small` triangles go
// on to depth 29, smaller ones stop at `small_depth`; an explicit --max-depth 12 is a plain limit.
static void check_sponza_limits(KdBuildQuality quality, std::uint32_t small_depth, std::uint32_t small) {
    KdBuildParams automatic;
    automatic.quality = quality;
    const KdDepthLimits l = KdDepthLimits::of(automatic, 66454);
    CHECK(l.max_depth == 29);
    CHECK(l.small_depth == small_depth);
    CHECK(l.small_triangles == small);
    CHECK(l.may_split(small_depth - 1, 1));
    CHECK_FALSE(l.may_split(small_depth, small));
    CHECK(l.may_split(small_depth, small + 1));
    CHECK_FALSE(l.may_split(29, 100000));
    KdBuildParams explicit_limit = automatic;
    explicit_limit.max_depth = 12;
    const KdDepthLimits e = KdDepthLimits::of(explicit_limit, 66454);
    CHECK(e.max_depth == 12);
    CHECK(e.small_depth == 12);
    CHECK(KdDepthLimits::of(automatic, 1).small_depth <= KdDepthLimits::of(automatic, 1).max_depth);
}

TEST_CASE("the automatic depth limits: 8 + 1.3 log2 N, and 4 + log2 N for small nodes", "[geometry][builder]") {
    check_sponza_limits(KdBuildQuality::high, 20, kSmallLeafTriangles);
}

TEST_CASE("a fast build stops small nodes two levels sooner and counts up to 32 triangles as small",
          "[geometry][builder]") {
    check_sponza_limits(KdBuildQuality::fast, 18, kFastSmallLeafTriangles);
}

TEST_CASE("below the small-node depth only nodes of more than the small size are split", "[geometry][builder]") {
    const KdBuildParams p = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(p.quality));
    const auto tris = ball_in_a_hall();
    const KdTree tree = build_sah_kd_tree(tris, p);
    CHECK(tree.limits.small_depth < tree.limits.max_depth);
    std::size_t deep = 0;
    for (const NodeFacts& f : inner_nodes(tree)) {
        CHECK(f.depth < tree.limits.max_depth);
        if (f.depth >= tree.limits.small_depth) {
            CHECK(f.triangles > tree.limits.small_triangles);
            ++deep;
        }
    }
    // The cluster sits deep below the cuts that separate it from the hall: its large nodes are
    // still split there.
    CHECK(deep > 0);
    CHECK(tree.stats.max_depth > tree.limits.small_depth);
    test::check_triangles(tris, test::random_rays(5000, 6, -1.5f, 2.5f), p);
}
