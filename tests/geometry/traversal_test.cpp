// Closest hits through the kd-tree equal a brute-force loop over all triangles.
#include <catch2/catch.hpp>

#include <cmath>

#include "builders/geometry/geometry_file_builder.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/geometry/kd_traversal.h"
#include "tests/geometry/random_scenes.h"

using namespace kdpm;

namespace {

// Counts disagreements; a different triangle at the same distance (a tie) is not one.
int compare_with_brute_force(const GeometryView& g, const std::vector<Ray>& rays) {
    int bad = 0;
    for (const Ray& r : rays) {
        const Hit a = closest_hit(g, r), b = closest_hit_brute_force(g, r);
        if (a.found() != b.found()) {
            ++bad;
            continue;
        }
        if (!a.found()) continue;
        if (std::fabs(a.t - b.t) > 1e-5f * std::fabs(b.t)) ++bad;
        if (occluded(g, Ray{r.origin, r.tmin, r.direction, b.t * 1.0001f}) != true) ++bad;
        if (occluded(g, Ray{r.origin, r.tmin, r.direction, b.t * 0.9999f}) &&
            closest_hit_brute_force(g, Ray{r.origin, r.tmin, r.direction, b.t * 0.9999f}).found() == false)
            ++bad;
    }
    return bad;
}

}  // namespace

TEST_CASE("closest hits through the tree match brute force on random soups", "[geometry][traversal]") {
    for (std::uint32_t seed : {1u, 2u, 3u}) {
        const std::uint32_t n = seed == 1 ? 50 : (seed == 2 ? 2000 : 8000);
        GeometryBuild b = build_geometry_file(scene_from_triangles(test::random_soup(n, seed)), KdBuildParams{});
        const auto bytes = b.writer.bytes();
        GeometryFile file = GeometryFile::from_bytes(bytes, "soup.kdg", true);
        CHECK(compare_with_brute_force(file.view(), test::random_rays(40000, seed + 100)) == 0);
    }
}

TEST_CASE("an empty scene misses every ray", "[geometry][traversal]") {
    GeometryBuild b = build_geometry_file(scene_from_triangles({}), KdBuildParams{});
    const auto bytes = b.writer.bytes();
    GeometryFile file = GeometryFile::from_bytes(bytes, "empty.kdg", true);
    for (const Ray& r : test::random_rays(100, 5)) CHECK_FALSE(closest_hit(file.view(), r).found());
}
