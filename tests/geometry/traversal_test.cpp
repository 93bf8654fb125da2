// Closest hits through the kd-tree equal a brute-force loop over all triangles (both qualities).
#include <catch2/catch.hpp>

#include "builders/geometry/scene_card.h"
#include "runtime/geometry/surface_normal.h"
#include "tests/geometry/geometry_check.h"
#include "tests/geometry/random_scenes.h"
#include "tests/support/run_command.h"

using namespace kdpm;

TEST_CASE("closest hits through the tree match brute force on random soups", "[geometry][traversal]") {
    const KdBuildParams p = test::quality_params(GENERATE(KdBuildQuality::high, KdBuildQuality::fast));
    INFO("quality: " << quality_name(p.quality));
    test::check_triangles(test::random_soup(60, 1, 0.3f), test::random_rays(30000, 101), p);
    test::check_triangles(test::random_soup(1500, 2), test::random_rays(50000, 102), p);
    test::check_triangles(test::random_soup(5000, 3, 0.02f), test::random_rays(20000, 103), p);
}

TEST_CASE("a fast tree cutting boxes in every exact node still finds every closest hit", "[geometry][traversal]") {
    // Boxes cut at the planes list triangles in leaves they only come near, never leave one out
    // (check_triangles validates leaf coverage exhaustively too).
    KdBuildParams p = test::quality_params(KdBuildQuality::fast);
    p.clip_below = 1u << 30;
    test::check_triangles(test::random_soup(1500, 2), test::random_rays(50000, 102), p);
    test::check_triangles(test::random_soup(5000, 3, 0.02f), test::random_rays(20000, 103), p);
}

TEST_CASE("closest hits match brute force on the shipped Cornell box", "[geometry][traversal]") {
    const Scene scene = load_scene_input(test::source_path("scenes/cornell-box/cornell-box.json"));
    const auto bytes = test::build_bytes(scene);
    const GeometryFile file = GeometryFile::from_bytes(bytes, "cornell-box.kdg");
    // Rays from inside the room and from the camera side, in random directions.
    auto rays = test::random_rays(60000, 7, -0.99f, 1.99f);
    auto outside = test::random_rays(40000, 8, -3.0f, 4.0f);
    rays.insert(rays.end(), outside.begin(), outside.end());
    CHECK(test::count_mismatches(file.view(), rays) == 0);
}

TEST_CASE("rays from the camera hit the back wall with its normal facing the camera", "[geometry][traversal]") {
    const Scene scene = load_scene_input(test::source_path("scenes/cornell-box/cornell-box.json"));
    const auto bytes = test::build_bytes(scene);
    const GeometryFile file = GeometryFile::from_bytes(bytes, "cornell-box.kdg");
    // Straight through the gap between the boxes at mid height: the back wall at z = -1.
    const Ray r{glm::vec3(0, 1.5f, 3.9f), 0.0f, glm::vec3(0, 0, -1), 1e30f};
    const Hit h = closest_hit(file.view(), r);
    REQUIRE(h.found());
    CHECK(h.t == Approx(4.9f));
    const glm::vec3 n = shading_normal(file.view(), h.triangle, h.u, h.v);
    CHECK(n.z == Approx(1.0f));
    const glm::vec3 p = surface_point(file.view().triangles[h.triangle], h.u, h.v);
    CHECK(p.z == Approx(-1.0f));
    CHECK_FALSE(occluded(file.view(), Ray{r.origin, 0.0f, r.direction, 4.8f}));
    CHECK(occluded(file.view(), Ray{r.origin, 0.0f, r.direction, 5.0f}));
}
