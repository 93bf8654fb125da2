// The shooter's closest-hit query is a parameter (what lets kdpm-bench run the same paths over
// Embree): with a brute-force intersector the paths are those of the kd-tree walk, and the query
// really is the one the paths use.
#include <catch2/catch.hpp>

#include <cmath>

#include "runtime/geometry/scene_traversal.h"
#include "runtime/photons/photon_shooter.h"
#include "runtime/photons/shoot_on_cpu.h"
#include "tests/photons/shooting_scenes.h"

using namespace kdpm;

namespace {

// Every triangle tested, nearest hit kept: the reference for the kd-tree walk.
struct BruteForceClosestHit {
    Hit operator()(const GeometryView& g, const Ray& ray) const { return closest_hit_brute_force(g, ray); }
};

struct NeverHits {
    Hit operator()(const GeometryView&, const Ray& ray) const { return miss(ray.tmax); }
};

}  // namespace

TEST_CASE("the shooter over a brute-force intersector stores the kd-tree shooter's photons", "[photons][shoot]") {
    auto scene = test::closed_box_with_glass_cube(0.7f);
    const GeometryView g = scene.view();
    ShootOptions options;
    options.photons = 3000;
    options.max_bounces = 6;
    options.seed = 5;
    const ShotPhotons tree = shoot_photons(g, options);
    const ShotPhotons brute = shoot_photons_on_cpu(g, options, BruteForceClosestHit{});
    REQUIRE(tree.info.caustic_count > 0);  // the glass and the mirror floor are on the paths
    // The same closest hits (both keep the first of equal-distance triangles in their own order,
    // and the box has no such ties on these paths), so the same hits in the same order.
    REQUIRE(brute.hits.size() == tree.hits.size());
    CHECK(brute.rays == tree.rays);
    CHECK(brute.info.caustic_count == tree.info.caustic_count);
    std::size_t same = 0;
    for (std::size_t i = 0; i < tree.hits.size(); ++i) {
        const PhotonHit &a = tree.hits[i], &b = brute.hits[i];
        same += a.path == b.path && a.flags == b.flags && a.position[0] == b.position[0] &&
                a.position[1] == b.position[1] && a.position[2] == b.position[2] && a.power[0] == b.power[0];
    }
    CHECK(same == tree.hits.size());
}

TEST_CASE("the shooter traces with the intersector it is given", "[photons][shoot]") {
    auto scene = test::closed_box(0.7f);
    ShootOptions options;
    options.photons = 500;
    const ShotPhotons none = shoot_photons_on_cpu(scene.view(), options, NeverHits{});
    CHECK(none.hits.empty());
    CHECK(none.rays == options.photons);  // one emission ray per path, then nothing to bounce from
    CHECK(none.info.emitted_count == options.photons);
    CHECK(none.info.emitted_power[0] > 0.0f);
}
