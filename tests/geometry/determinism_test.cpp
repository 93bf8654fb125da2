// The same input gives byte-identical files whatever the number of threads.
#include <catch2/catch.hpp>

#include "runtime/backend/thread_limit.h"
#include "tests/geometry/geometry_check.h"
#include "tests/geometry/random_scenes.h"

using namespace kdpm;

TEST_CASE("one and two threads build byte-identical files", "[geometry][determinism]") {
    // Large enough for several subtrees to be built in parallel, and for a fast build to bin
    // nodes in several parallel chunks.
    KdBuildParams params;
    params.quality = GENERATE(KdBuildQuality::high, KdBuildQuality::fast);
    INFO("quality: " << quality_name(params.quality));
    const Scene scene = scene_from_triangles(test::random_soup(40000, 31, 0.05f));
    std::vector<std::uint8_t> one, two;
    {
        ThreadLimit limit(1);
        one = test::build_bytes(scene, params);
    }
    {
        ThreadLimit limit(2);
        two = test::build_bytes(scene, params);
    }
    REQUIRE(one.size() == two.size());
    CHECK(one == two);
}
