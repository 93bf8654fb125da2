// The four-wide leaf test (leaf_triangles_simd.h) equals the scalar leaf loop bit for bit: the
// same closest triangle, t, u and v (ties go to the first in leaf order), and the same
// occlusion verdict, on leaves of every size, with degenerate, NaN and duplicated triangles.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "runtime/geometry/kd_traversal.h"
#include "runtime/geometry/leaf_triangles_simd.h"
#include "tests/geometry/random_scenes.h"

using namespace kdpm;

#if defined(KDPM_LEAF_SIMD)
namespace {

// The walk's leaf loop as written for the GPU: one triangle after another.
Hit scalar_closest(const GeometryView& g, const Ray& ray, std::uint32_t first, std::uint32_t count, Hit hit) {
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::uint32_t tri = g.leaf_indices[first + i];
        float t, u, v;
        if (intersect_triangle(g.triangles[tri], ray.origin, ray.direction, ray.tmin, hit.t, t, u, v))
            hit = Hit{t, tri, u, v};
    }
    return hit;
}

bool scalar_any(const GeometryView& g, const Ray& ray, std::uint32_t first, std::uint32_t count) {
    for (std::uint32_t i = 0; i < count; ++i) {
        float t, u, v;
        if (intersect_triangle(g.triangles[g.leaf_indices[first + i]], ray.origin, ray.direction, ray.tmin, ray.tmax,
                               t, u, v))
            return true;
    }
    return false;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

TEST_CASE("the four-wide leaf test equals the scalar leaf loop bit for bit", "[geometry][traversal][simd]") {
    // A soup of small triangles in the unit cube, plus exact duplicates (ties in t), zero-area
    // triangles and one with a NaN vertex.
    std::vector<TriangleRecord> tris = test::random_soup(400, 11, 0.4f);
    for (std::uint32_t i = 0; i < 40; ++i) tris.push_back(tris[i * 7]);
    TriangleRecord flat = tris[3];
    for (int a = 0; a < 3; ++a) flat.e2[a] = flat.e1[a] * 0.5f;
    tris.push_back(flat);
    TriangleRecord nan_tri = tris[5];
    nan_tri.v0[1] = std::numeric_limits<float>::quiet_NaN();
    tris.push_back(nan_tri);

    std::mt19937 rng(12);
    std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(tris.size()) - 1);
    std::uniform_int_distribution<std::uint32_t> size(1, 13);
    // Leaves of 1..13 triangles; each leaf also repeats one of its own triangles now and then,
    // so that equal t within one group of four and across groups both occur.
    std::vector<std::uint32_t> leaf_indices;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> leaves;
    for (int l = 0; l < 3000; ++l) {
        const std::uint32_t first = static_cast<std::uint32_t>(leaf_indices.size()), n = size(rng);
        for (std::uint32_t i = 0; i < n; ++i)
            leaf_indices.push_back(i > 0 && rng() % 5 == 0 ? leaf_indices[first + rng() % i] : pick(rng));
        leaves.emplace_back(first, n);
    }
    GeometryView g;
    g.triangles = tris.data();
    g.triangle_count = static_cast<std::uint32_t>(tris.size());
    g.leaf_indices = leaf_indices.data();
    g.leaf_index_count = static_cast<std::uint32_t>(leaf_indices.size());

    // Random rays, and rays aimed at a point of one of the leaf's own triangles (most of them hit).
    const std::vector<Ray> rays = test::random_rays(200, 13, -0.5f, 1.5f);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::uint64_t hits = 0, occluded_rays = 0, checked = 0;
    for (const auto& [first, count] : leaves) {
        for (std::size_t r = 0; r < 60; ++r) {
            Ray ray = rays[(r * 7 + first) % rays.size()];
            if (r % 2 == 1) {
                const TriangleRecord& t = tris[leaf_indices[first + rng() % count]];
                float a = unit(rng), b = unit(rng);
                if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
                for (int c = 0; c < 3; ++c) ray.direction[c] = t.v0[c] + a * t.e1[c] + b * t.e2[c] - ray.origin[c];
            }
            // Short segments and a limit from an earlier hit, as the walk passes them.
            const float limits[] = {std::numeric_limits<float>::infinity(), 1.0f, 0.3f};
            for (const float tmax : limits) {
                ray.tmax = tmax;
                const Hit want = scalar_closest(g, ray, first, count, miss(tmax));
                Hit got = miss(tmax);
                closest_in_leaf(g, ray, first, count, got);
                ++checked;
                hits += want.found();
                REQUIRE(got.triangle == want.triangle);
                REQUIRE(same_bits(got.t, want.t));
                REQUIRE(same_bits(got.u, want.u));
                REQUIRE(same_bits(got.v, want.v));
                const bool any = scalar_any(g, ray, first, count);
                occluded_rays += any;
                REQUIRE(any_in_leaf(g, ray, first, count) == any);
            }
        }
    }
    // The comparison must have seen hits and misses alike.
    CHECK(hits > checked / 4);
    CHECK(hits < checked);
    CHECK(occluded_rays > checked / 4);
}

TEST_CASE("a ray in the plane of a leaf's triangles and a ray along an edge hit as the scalar loop says",
          "[geometry][traversal][simd]") {
    // Two triangles sharing the edge x = y in the z = 0 plane, and one in the plane x = 0.5.
    std::vector<TriangleRecord> tris(3);
    auto set = [](TriangleRecord& t, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
        for (int i = 0; i < 3; ++i) {
            t.v0[i] = a[i];
            t.e1[i] = b[i] - a[i];
            t.e2[i] = c[i] - a[i];
        }
    };
    set(tris[0], {0, 0, 0}, {1, 0, 0}, {1, 1, 0});
    set(tris[1], {0, 0, 0}, {1, 1, 0}, {0, 1, 0});
    set(tris[2], {0.5f, -1, -1}, {0.5f, 2, -1}, {0.5f, -1, 2});
    std::vector<std::uint32_t> leaf_indices = {0, 1, 2};
    GeometryView g;
    g.triangles = tris.data();
    g.triangle_count = 3;
    g.leaf_indices = leaf_indices.data();
    g.leaf_index_count = 3;
    const float inf = std::numeric_limits<float>::infinity();
    const Ray rays[] = {
        {{0.25f, 0.25f, 1.0f}, 0.0f, {0, 0, -1}, inf},     // through triangle 0 only
        {{0.5f, 0.5f, 1.0f}, 0.0f, {0, 0, -1}, inf},       // on the shared edge: both, a tie in t
        {{-1.0f, 0.5f, 0.0f}, 0.0f, {1, 0, 0}, inf},       // in the z = 0 plane: det 0 for 0 and 1
        {{0.5f, 0.5f, 0.5f}, 0.0f, {0, 0, 0}, inf},        // zero direction
        {{0.25f, 0.25f, 1.0f}, 0.0f, {0, 0, -1}, 1.0f},    // the hit exactly at tmax: excluded
    };
    for (const Ray& ray : rays) {
        const Hit want = scalar_closest(g, ray, 0, 3, miss(ray.tmax));
        Hit got = miss(ray.tmax);
        closest_in_leaf(g, ray, 0, 3, got);
        CHECK(got.triangle == want.triangle);
        CHECK(same_bits(got.t, want.t));
        CHECK(any_in_leaf(g, ray, 0, 3) == scalar_any(g, ray, 0, 3));
    }
    // The shared edge goes to the first triangle of the leaf, as in the scalar loop.
    Hit edge = miss(inf);
    closest_in_leaf(g, rays[1], 0, 3, edge);
    CHECK(edge.triangle == 0u);
}
#else
TEST_CASE("the four-wide leaf test equals the scalar leaf loop bit for bit", "[geometry][traversal][simd]") {
    WARN("no SSE2 leaf test on this target (the walk uses the scalar loop): skipped");
}
#endif
