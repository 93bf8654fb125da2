// kdpm-bench's Embree photon tracer runs kdpm's shooter over rtcIntersect1, so it must store the
// photons kdpm stores (up to float differences in hit points), on diffuse, textured, mirror and
// glass surfaces; and the agreement figure the bench prints must see a difference when there is one.
#include <catch2/catch.hpp>

#include <vector>

#include "builders/geometry/geometry_file_builder.h"
#include "builders/geometry/scene_card.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_shooter.h"
#include "tests/photons/shooting_scenes.h"
#include "tests/support/run_command.h"
#include "tools/bench/photon_agreement.h"
#ifdef KDPM_HAVE_EMBREE
#include "tools/bench/peer_embree_photons.h"
#endif

using namespace kdpm;

namespace {

PhotonHit hit_of(std::uint32_t path, std::uint32_t bounce, bool caustic, float x) {
    PhotonHit h{};
    h.path = path;
    h.flags = make_photon_flags(bounce, caustic);
    h.position[0] = x;
    return h;
}

}  // namespace

TEST_CASE("compare_photons counts both maps and the paths whose hits match", "[tools][bench]") {
    const std::vector<PhotonHit> ours = {hit_of(0, 0, false, 1.0f), hit_of(0, 1, true, 2.0f), hit_of(2, 0, false, 3.0f),
                                         hit_of(5, 0, false, 4.0f)};
    const bench::PhotonAgreement same = bench::compare_photons(ours, ours, 0.0f);
    CHECK(same.paths == 3);
    CHECK(same.same_paths == 3);
    CHECK(same.ours_global == 4);
    CHECK(same.ours_caustic == 1);
    CHECK(same.path_agreement() == 1.0);

    // Path 2 moved beyond the tolerance, path 5 missing, path 7 only theirs, path 0 one hit short.
    std::vector<PhotonHit> theirs = {hit_of(0, 0, false, 1.0f), hit_of(2, 0, false, 3.5f), hit_of(7, 0, false, 4.0f)};
    const bench::PhotonAgreement a = bench::compare_photons(ours, theirs, 0.1f);
    CHECK(a.paths == 4);
    CHECK(a.same_paths == 0);
    CHECK(a.theirs_global == 3);
    CHECK(a.theirs_caustic == 0);
    CHECK(a.global_agreement() == Approx(0.75));
    CHECK(a.caustic_agreement() == 0.0);
    // Within the tolerance the moved hit counts as the same.
    theirs[1].position[0] = 3.05f;
    CHECK(bench::compare_photons(ours, theirs, 0.1f).same_paths == 1);
}

#ifdef KDPM_HAVE_EMBREE

namespace {

GeometryFile geometry_of_card(const std::string& card) {
    auto build = build_geometry_file(load_scene_input(test::source_path(card)), KdBuildParams{});
    return GeometryFile::from_bytes(build.writer.bytes(), card);
}

// `caustics`: whether the scene has specular surfaces that store caustic photons.
void check_same_photons(const GeometryFile& scene, std::uint32_t bounces, bool caustics) {
    const GeometryView g = scene.view();
    ShootOptions options;
    options.photons = 20000;
    options.max_bounces = bounces;
    options.seed = 3;
    const ShotPhotons ours = shoot_photons(g, options);
    const ShotPhotons theirs = bench::EmbreePhotonTracer(g, 2).shoot(options);
    REQUIRE(ours.hits.size() >= 500);
    REQUIRE((ours.info.caustic_count > 0) == caustics);
    float extent = 0.0f;
    for (int a = 0; a < 3; ++a) extent = std::max(extent, g.info.bounds_max[a] - g.info.bounds_min[a]);
    const bench::PhotonAgreement a = bench::compare_photons(ours.hits, theirs.hits, 1e-5f * extent);
    INFO("stored " << a.ours_global << " / " << a.theirs_global << ", caustic " << a.ours_caustic << " / "
                   << a.theirs_caustic << ", same paths " << a.same_paths << " of " << a.paths);
    CHECK(a.global_agreement() >= 0.999);
    CHECK(a.caustic_agreement() >= 0.999);
    CHECK(a.path_agreement() >= 0.999);
    // Rays count the roulette's decisions too (a surviving photon traces one more ray, stored or not).
    CHECK(bench::PhotonAgreement::count_ratio(ours.rays, theirs.rays) >= 0.999);
    CHECK(theirs.info.stored_count == theirs.hits.size());
    CHECK(theirs.info.caustic_count == a.theirs_caustic);
    CHECK(theirs.info.emitted_count == ours.info.emitted_count);
}

}  // namespace

TEST_CASE("the Embree photon tracer stores kdpm's photons: diffuse Cornell box", "[tools][bench][embree]") {
    check_same_photons(geometry_of_card("scenes/cornell-box/cornell-box.json"), 4, false);
}

TEST_CASE("the Embree photon tracer stores kdpm's photons: textured quad", "[tools][bench][embree]") {
    const GeometryFile quad = geometry_of_card("scenes/textured-quad/textured-quad.json");
    REQUIRE(quad.view().texture_count == 1);  // the roulette reads the checker's albedo
    check_same_photons(quad, 2, false);
}

TEST_CASE("the Embree photon tracer stores kdpm's photons: mirror floor and glass cube", "[tools][bench][embree]") {
    check_same_photons(test::closed_box_with_glass_cube(0.7f), 6, true);
}

#else

TEST_CASE("the Embree photon tracer stores kdpm's photons", "[tools][bench][embree]") {
    WARN("Embree 3 is not installed (Debian package libembree-dev): the Embree photon tracer is not built: skipped");
}

#endif
