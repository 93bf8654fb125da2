// Degenerate input gives a correct tree: zero-area and NaN triangles, an empty scene, everything
// coplanar, one huge triangle, duplicates; for both build qualities.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "builders/geometry/sah/sah_kd_builder.h"
#include "tests/geometry/geometry_check.h"
#include "tests/geometry/random_scenes.h"

using namespace kdpm;

TEST_CASE("zero-area and NaN triangles are kept as records but left out of the tree", "[geometry][degenerate]") {
    const KdBuildParams params = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(params.quality));
    auto tris = test::random_soup(500, 11);
    float a[3] = {0.5f, 0.5f, 0.5f}, b[3] = {0.6f, 0.6f, 0.6f}, c[3] = {0.7f, 0.7f, 0.7f};
    tris.push_back(make_triangle(a, a, a, 0, 0));  // a point
    tris.push_back(make_triangle(a, b, c, 0, 0));  // a line
    float nan[3] = {std::numeric_limits<float>::quiet_NaN(), 0.5f, 0.5f};
    tris.push_back(make_triangle(nan, b, c, 0, 0));
    float inf[3] = {std::numeric_limits<float>::infinity(), 0.5f, 0.5f};
    tris.push_back(make_triangle(a, inf, c, 0, 0));
    const KdTree tree = build_sah_kd_tree(tris, params);
    for (std::uint32_t i : tree.leaf_indices) CHECK(i < 500);
    test::check_triangles(tris, test::random_rays(20000, 12), params);
}

TEST_CASE("an empty scene gives one empty leaf and misses every ray", "[geometry][degenerate]") {
    const KdBuildParams params = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(params.quality));
    const KdTree tree = build_sah_kd_tree({}, params);
    REQUIRE(tree.nodes.size() == 1);
    CHECK(tree.nodes[0].is_leaf());
    CHECK(tree.nodes[0].count() == 0);
    test::check_triangles({}, test::random_rays(1000, 13), params);
}

TEST_CASE("a coplanar scene builds and traverses correctly", "[geometry][degenerate]") {
    const KdBuildParams params = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(params.quality));
    auto tris = test::random_soup(800, 14);
    for (auto& t : tris) {
        t.v0[2] = 0.5f;
        t.e1[2] = 0.0f;
        t.e2[2] = 0.0f;
    }
    test::check_triangles(tris, test::random_rays(20000, 15), params);
    // Rays straight down onto the plane hit wherever brute force does.
    std::vector<Ray> down;
    for (const Ray& r : test::random_rays(5000, 16)) down.push_back(Ray{{r.origin.x, r.origin.y, 2.0f}, 0.0f, {0, 0, -1}, 1e30f});
    test::check_triangles(tris, down, params);
}

TEST_CASE("one huge triangle among small ones", "[geometry][degenerate]") {
    const KdBuildParams params = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(params.quality));
    auto tris = test::random_soup(1000, 17);
    float a[3] = {-1e4f, -1e4f, 0.3f}, b[3] = {1e4f, -1e4f, 0.6f}, c[3] = {0.0f, 1e4f, 0.45f};
    tris.push_back(make_triangle(a, b, c, 0, 0));
    test::check_triangles(tris, test::random_rays(20000, 18), params);
}

TEST_CASE("a single triangle and exact duplicates", "[geometry][degenerate]") {
    const KdBuildParams params = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(params.quality));
    float a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
    std::vector<TriangleRecord> one{make_triangle(a, b, c, 0, 0)};
    test::check_triangles(one, test::random_rays(2000, 19), params);
    auto tris = test::random_soup(300, 20);
    auto twice = tris;
    twice.insert(twice.end(), tris.begin(), tris.end());
    // The copies differ in source index only: the tree holds the first of each.
    for (std::size_t i = 300; i < twice.size(); ++i) twice[i].source_index = static_cast<std::uint32_t>(i);
    const KdTree tree = build_sah_kd_tree(twice, params);
    CHECK(tree.repeated_triangles == 300);
    for (std::uint32_t i : tree.leaf_indices) CHECK(i < 300);
    test::check_triangles(twice, test::random_rays(10000, 21), params);
}

TEST_CASE("a tiny depth limit still gives a correct tree", "[geometry][degenerate]") {
    KdBuildParams p = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(p.quality));
    p.max_depth = 2;
    test::check_triangles(test::random_soup(2000, 22), test::random_rays(5000, 23), p);
}
