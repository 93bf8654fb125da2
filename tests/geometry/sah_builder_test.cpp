// The O(N log N) builder reaches the same tree and SAH cost as the O(N^2) reference builder; a fast
// build equals it below the binning size (when it clips there) and stays close to its SAH cost
// above, and with boxes cut instead of triangles clipped in its small nodes.
#include <catch2/catch.hpp>

#include <cstring>

#include "builders/geometry/sah/sah_kd_builder.h"
#include "tests/geometry/random_scenes.h"
#include "tests/geometry/reference_kd_builder.h"

using namespace kdpm;

namespace {

// Axis-aligned unit quads on a grid: many planar triangles and equal split positions.
std::vector<TriangleRecord> quad_grid() {
    std::vector<TriangleRecord> tris;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const float x = static_cast<float>(i), y = static_cast<float>(j), z = static_cast<float>((i + j) % 3);
            float a[3] = {x, y, z}, b[3] = {x + 1, y, z}, c[3] = {x + 1, y + 1, z}, d[3] = {x, y + 1, z};
            tris.push_back(make_triangle(a, b, c, 0, 0));
            tris.push_back(make_triangle(a, c, d, 0, 0));
            float e[3] = {x, y, 0}, f[3] = {x, y + 1, 0}, g[3] = {x, y + 1, 2};
            tris.push_back(make_triangle(e, f, g, 0, 0));  // planar in x
        }
    return tris;
}

void check_same_tree(const std::vector<TriangleRecord>& tris, KdBuildParams params) {
    params.quality = KdBuildQuality::high;
    const KdTree fast = build_sah_kd_tree(tris, params);
    const KdTree slow = test::ReferenceKdBuilder(tris, params).build();
    CHECK(fast.stats.sah_cost == Approx(slow.stats.sah_cost).epsilon(1e-9));
    CHECK(fast.stats.sah_cost < params.intersection_cost * static_cast<double>(tris.size()) + 1e-9);
    REQUIRE(fast.nodes.size() == slow.nodes.size());
    CHECK(std::memcmp(fast.nodes.data(), slow.nodes.data(), fast.nodes.size() * sizeof(KdNode)) == 0);
    CHECK(fast.leaf_indices == slow.leaf_indices);
}

}  // namespace

TEST_CASE("the SAH builder matches the O(N^2) reference on random soups", "[geometry][builder]") {
    // 700 triangles: more than a thousand events per axis, sorted by radix passes.
    for (std::uint32_t n : {1u, 7u, 40u, 150u, 400u, 700u}) {
        INFO("triangles: " << n);
        check_same_tree(test::random_soup(n, n, 0.2f), KdBuildParams{});
    }
}

TEST_CASE("the SAH builder matches the reference with other parameters", "[geometry][builder]") {
    KdBuildParams p;
    p.traversal_cost = 0.3f;
    p.intersection_cost = 4.0f;
    p.empty_bonus = 0.5f;
    p.leaf_size = 2;
    check_same_tree(test::random_soup(200, 9, 0.3f), p);
    p.max_depth = 3;
    check_same_tree(test::random_soup(200, 9, 0.3f), p);
}

TEST_CASE("the SAH builder matches the reference on planar grids and duplicates", "[geometry][builder]") {
    auto grid = quad_grid();
    check_same_tree(grid, KdBuildParams{});
    auto soup = test::random_soup(60, 4, 0.2f);
    auto doubled = soup;
    doubled.insert(doubled.end(), soup.begin(), soup.end());
    check_same_tree(doubled, KdBuildParams{});
}

TEST_CASE("a fast build clipping everywhere is the exact build when no node reaches the binning size", "[geometry][builder]") {
    const auto soup = test::random_soup(3000, 41, 0.1f);
    KdBuildParams p;
    // One plain depth limit for both: automatically, a fast build stops small nodes sooner.
    p.max_depth = 22;
    p.quality = KdBuildQuality::high;
    const KdTree high = build_sah_kd_tree(soup, p);
    p.quality = KdBuildQuality::fast;
    p.exact_below = 3001;
    p.clip_below = 0;
    const KdTree fast = build_sah_kd_tree(soup, p);
    REQUIRE(fast.nodes.size() == high.nodes.size());
    CHECK(std::memcmp(fast.nodes.data(), high.nodes.data(), fast.nodes.size() * sizeof(KdNode)) == 0);
    CHECK(fast.leaf_indices == high.leaf_indices);
}

TEST_CASE("a fast build bins its upper levels and stays within 5% of the exact SAH cost", "[geometry][builder]") {
    const auto soup = test::random_soup(20000, 42, 0.05f);
    KdBuildParams p;
    p.quality = KdBuildQuality::high;
    const KdTree high = build_sah_kd_tree(soup, p);
    p.quality = KdBuildQuality::fast;
    p.exact_below = 256;
    p.clip_below = 0;
    const KdTree fast = build_sah_kd_tree(soup, p);
    // Binned planes are not the exact optimum: the trees differ, the cost barely does.
    CHECK(fast.leaf_indices != high.leaf_indices);
    CHECK(fast.stats.sah_cost <= 1.05 * high.stats.sah_cost);
}

TEST_CASE("a fast build cuts boxes instead of triangles below clip_below, for a smaller tree of nearly the same cost",
          "[geometry][builder]") {
    // Random triangles in every orientation: the worst case for boxes (an architectural scene's
    // are mostly axis-aligned: Sponza and Conference cost about 1% more at the default).
    const auto soup = test::random_soup(3000, 41, 0.1f);
    KdBuildParams p;
    p.quality = KdBuildQuality::fast;
    p.exact_below = 3001;  // no binning: only the cut differs
    p.clip_below = 0;
    const KdTree clipped = build_sah_kd_tree(soup, p);
    p.clip_below = KdBuildParams{}.clip_below;
    const KdTree cut = build_sah_kd_tree(soup, p);
    CHECK(cut.nodes.size() < clipped.nodes.size());
    CHECK(cut.stats.sah_cost > clipped.stats.sah_cost);  // boxes bound the triangles less tightly
    CHECK(cut.stats.sah_cost <= 1.06 * clipped.stats.sah_cost);
}

TEST_CASE("a build's statistics, taken while its pieces are built, are measure_kd_tree's bit for bit",
          "[geometry][builder]") {
    // 20,000 triangles: several pieces built apart (split at the top, flat below) in both qualities.
    const auto soup = test::random_soup(20000, 43, 0.05f);
    for (KdBuildQuality q : {KdBuildQuality::high, KdBuildQuality::fast}) {
        INFO("quality: " << quality_name(q));
        KdBuildParams p;
        p.quality = q;
        const KdTree tree = build_sah_kd_tree(soup, p);
        const KdTreeStats walked = measure_kd_tree(tree.nodes, tree.bounds, p);
        CHECK(tree.stats.nodes == walked.nodes);
        CHECK(tree.stats.leaves == walked.leaves);
        CHECK(tree.stats.empty_leaves == walked.empty_leaves);
        CHECK(tree.stats.leaf_references == walked.leaf_references);
        CHECK(tree.stats.max_depth == walked.max_depth);
        CHECK(tree.stats.max_leaf_triangles == walked.max_leaf_triangles);
        CHECK(std::memcmp(&tree.stats.mean_leaf_triangles, &walked.mean_leaf_triangles, sizeof(double)) == 0);
        CHECK(std::memcmp(&tree.stats.sah_cost, &walked.sah_cost, sizeof(double)) == 0);
        CHECK(tree.stats.leaves > 1000);
    }
}
