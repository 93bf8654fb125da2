// The real Sponza (66k triangles, with near-flat slivers and duplicates): the exhaustive check
// passes and camera rays through the tree match brute force, for both qualities. Skipped without ../shared/scenes.
#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

#include "builders/geometry/import/scene_import.h"
#include "tests/geometry/geometry_check.h"
#include "tests/support/run_command.h"

using namespace kdpm;

TEST_CASE("Sponza builds a sound tree that agrees with brute force", "[geometry][large]") {
    const std::string dir = test::shared_scenes_dir();
    const auto mesh = std::filesystem::path(dir) / "sponza" / "sponza.obj";
    if (dir.empty() || !std::filesystem::exists(mesh)) {
        WARN("../shared/scenes/sponza not found (set KDPM_SCENES): skipped");
        return;
    }
    const Scene scene = import_mesh(mesh);
    REQUIRE(scene.triangles.size() == 66454);
    KdBuildParams params;
    params.quality = GENERATE(KdBuildQuality::high, KdBuildQuality::fast);
    INFO("quality: " << quality_name(params.quality));
    const auto bytes = test::build_bytes(scene, params);
    ValidationOptions exhaustive;
    exhaustive.exhaustive = true;
    REQUIRE_NOTHROW(validate_file(ContainerReader::from_bytes(bytes, "sponza.kdg"), exhaustive));
    const GeometryFile file = GeometryFile::from_bytes(bytes, "sponza.kdg");
    // Rays from the suggested camera position and from random points in the atrium.
    std::mt19937 rng(77);
    std::normal_distribution<float> g(0.0f, 1.0f);
    std::uniform_real_distribution<float> x(-11.0f, 11.0f), y(0.2f, 15.0f), z(-3.0f, 3.0f);
    std::vector<Ray> rays;
    for (int i = 0; i < 3000; ++i) {
        const glm::vec3 origin = i % 2 ? glm::vec3(-10.5f, 1.8f, 0.0f) : glm::vec3(x(rng), y(rng), z(rng));
        rays.push_back(Ray{origin, 0.0f, glm::vec3(g(rng), g(rng), g(rng)), 1e30f});
    }
    CHECK(test::count_mismatches(file.view(), rays) == 0);
}
