// The irradiance cache of final gathering: the record tree's lookup against brute force, exact
// interpolation on a flat plane under uniform and linearly varying light, and on the Cornell box
// the cached image against the uncached one and the path tracer, with gather rays at far fewer
// points than are shaded; a cache kept between frames.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "runtime/render/final_gather/irradiance_record_tree.h"
#include "runtime/render/renderer.h"
#include "tests/runtime/built_scene.h"
#include "tests/runtime/cornell_box_runs.h"
#include "tests/runtime/image_stats.h"
#include "tests/runtime/in_memory_photons.h"
#include "tests/support/run_command.h"

using namespace kdpm;
using kdpm::test::mean_of;
using kdpm::test::relative_mse;

namespace {

IrradianceRecord record_at(glm::vec3 p, glm::vec3 n, float radius, glm::vec3 e) {
    IrradianceRecord r;
    r.position = p;
    r.normal = n;
    r.radius = radius;
    r.irradiance = e;
    for (int c = 0; c < 3; ++c) r.rotation[c] = r.translation[c] = glm::vec3(0.0f);
    return r;
}

}  // namespace

TEST_CASE("the record tree finds exactly the records a brute-force scan finds valid", "[render][irradiance-cache]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), size(0.02f, 0.6f);
    auto direction = [&] {
        glm::vec3 d;
        do d = glm::vec3(unit(rng), unit(rng), unit(rng));
        while (glm::length(d) < 0.1f || glm::length(d) > 1.0f);
        return glm::normalize(d);
    };
    const float accuracy = GENERATE(0.1f, 0.3f, 1.0f);
    IrradianceRecordTree tree(accuracy);
    // Added in three batches, as the cache's levels add them.
    for (int batch = 0; batch < 3; ++batch) {
        std::vector<IrradianceRecord> records;
        for (int i = 0; i < 700; ++i)
            records.push_back(record_at(glm::vec3(unit(rng), unit(rng), unit(rng)) * 2.0f,
                                        glm::normalize(glm::vec3(0, 0, 1) + 0.5f * direction()), size(rng),
                                        glm::vec3(1.0f)));
        tree.add(records);
    }
    const IrradianceTreeView view = tree.view();
    std::size_t found_total = 0;
    std::uniform_int_distribution<std::size_t> any(0, tree.records().size() - 1);
    for (int q = 0; q < 2000; ++q) {
        // Near a record, where several may be valid.
        const IrradianceRecord& near = tree.records()[any(rng)];
        const glm::vec3 p = near.position + glm::vec3(unit(rng), unit(rng), unit(rng)) * 0.01f;
        const glm::vec3 n = glm::normalize(near.normal + 0.05f * direction());
        std::vector<std::uint32_t> found, expected;
        view.for_each_valid(p, n, [&](std::uint32_t i, float) { found.push_back(i); });
        for (std::uint32_t i = 0; i < tree.records().size(); ++i) {
            const float e = record_error(tree.records()[i], p, n);
            if (e >= 0.0f && e < accuracy) expected.push_back(i);
        }
        std::sort(found.begin(), found.end());
        REQUIRE(found == expected);
        found_total += found.size();
    }
    CHECK(found_total > 300);  // the queries do find records
}

TEST_CASE("a small record clamps its neighbours' radii by their distance, both ways and in later batches",
          "[render][irradiance-cache]") {
    const glm::vec3 up(0, 0, 1), e(1.0f);
    IrradianceRecordTree tree(0.2f);
    tree.add({record_at({0, 0, 0}, up, 1.0f, e), record_at({5, 0, 0}, up, 1.0f, e)});
    CHECK(tree.records()[0].radius == 1.0f);  // 5 apart: neither clamps the other
    // Out in the open the big record is valid at x = 0.19; then a small one appears at x = 0.3.
    glm::vec3 unused;
    REQUIRE(tree.view().interpolate({0.19f, 0, 0}, up, unused));
    tree.add({record_at({0.3f, 0, 0}, up, 0.01f, e), record_at({0.4f, 0, 0}, up, 2.0f, e)});
    const auto& r = tree.records();
    CHECK(r[0].radius == Approx(0.31f));  // the old record, by the new small one
    CHECK(r[3].radius == Approx(0.11f));  // a new record, by the small one beside it
    CHECK(r[2].radius == Approx(0.01f));
    CHECK(r[1].radius == 1.0f);           // 4.6 from the small one: R 1 < 0.01 + 4.6
    // The tree was refitted to the clamped spheres: reach 0.2 * 0.31 no longer gets to 0.19.
    std::vector<std::uint32_t> valid;
    tree.view().for_each_valid({0.19f, 0, 0}, up, [&](std::uint32_t i, float) { valid.push_back(i); });
    CHECK(valid.empty());
}

TEST_CASE("records on a flat plane interpolate uniform and linearly varying irradiance exactly",
          "[render][irradiance-cache]") {
    // Irradiance E(p) = e0 + g . p on the plane z = 0: records carry it and its gradient g, so
    // every weighted blend of their first-order extrapolations is E(p) again.
    const glm::vec3 e0(2.0f, 1.0f, 0.5f);  // E >= 0.3 on [0, 4]^2
    const bool linear = GENERATE(false, true);
    const glm::vec3 g = linear ? glm::vec3(0.1f, -0.05f, 0.0f) : glm::vec3(0.0f);  // positive on the plane
    auto field = [&](glm::vec3 p) { return e0 + glm::vec3(glm::dot(g, p)); };
    const glm::vec3 up(0, 0, 1);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<IrradianceRecord> records;
    for (int i = 0; i < 300; ++i) {
        const glm::vec3 p(unit(rng) * 4.0f, unit(rng) * 4.0f, 0.0f);
        IrradianceRecord r = record_at(p, up, 0.5f + unit(rng), field(p));
        for (int c = 0; c < 3; ++c) r.translation[c] = g;
        records.push_back(r);
    }
    IrradianceRecordTree tree(0.4f);
    tree.add(records);
    int interpolated = 0;
    for (int q = 0; q < 1000; ++q) {
        const glm::vec3 p(unit(rng) * 4.0f, unit(rng) * 4.0f, 0.0f);
        glm::vec3 e;
        if (!tree.view().interpolate(p, up, e)) continue;
        ++interpolated;
        const glm::vec3 want = field(p);
        for (int c = 0; c < 3; ++c) REQUIRE(e[c] == Approx(want[c]).epsilon(1e-5));
    }
    CHECK(interpolated > 900);
}

TEST_CASE("final gathering with the irradiance cache on the Cornell box agrees with the uncached image and the "
          "path tracer, gathering at far fewer points than it shades",
          "[render][final-gather][irradiance-cache][cornell]") {
    test::CornellBoxRuns box;
    box.shoot_photons();
    const std::string kdp = box.build_photons("cb.kdp");
    const std::string options = "--mode final-gather --spp 16 --gather-rays 16";
    const std::string cached_exr = (box.dir / "cached.exr").string();
    const std::string said = box.run("kdpm-render " + box.kdg + " " + kdp + " " + options +
                                     " --width 32 --height 32 --backend cpu --tonemap none -o " + cached_exr);
    const std::vector<float> cached = test::read_exr(cached_exr);
    const std::vector<float> uncached = box.render(box.kdg + " " + kdp, options + " --irradiance-cache off", "off");
    const std::vector<float> path = box.render("--mode path --spp 16", "path");  // the card's photons: every bounce
    // Equal spp keeps the camera rays (and the emitter's antialiasing) the same in every mode.
    const double relmse_cached = relative_mse(cached, path), relmse_uncached = relative_mse(uncached, path);
    const double relmse_between = relative_mse(cached, uncached);
    INFO("means: cached " << mean_of(cached) << ", uncached " << mean_of(uncached) << ", path " << mean_of(path)
                          << "; relMSE against path: cached " << relmse_cached << ", uncached " << relmse_uncached
                          << "; cached against uncached " << relmse_between);
    CHECK(mean_of(cached) == Approx(mean_of(uncached)).epsilon(0.01));
    CHECK(mean_of(cached) == Approx(mean_of(path)).epsilon(0.01));
    // Every horizontal third: the interpolation must not shift light between regions.
    const std::size_t third = cached.size() / 3;
    for (int t = 0; t < 3; ++t) {
        INFO("third " << t);
        CHECK(mean_of(cached, t * third, (t + 1) * third) ==
              Approx(mean_of(uncached, t * third, (t + 1) * third)).epsilon(0.02));
    }
    // Interpolation smooths the gather noise; it must not add error of its own. Observed: 1057
    // records for 14675 points; relMSE against path 0.019 cached, 0.018 uncached (mostly the
    // path tracer's own noise at 16 spp), 0.0016 between the two; means within 0.3 %.
    CHECK(relmse_cached < 1.2 * relmse_uncached);
    CHECK(relmse_between < 0.005);

    unsigned long long records = 0, points = 0;
    const auto at = said.find("irradiance cache:");
    REQUIRE(at != std::string::npos);
    REQUIRE(std::sscanf(said.c_str() + at, "irradiance cache: gather rays at %llu records for %llu diffuse points",
                        &records, &points) == 2);
    INFO(records << " records for " << points << " points");
    CHECK(points >= 32ull * 32 * 16 / 2);  // most of 16 samples of 32x32 pixels reach a diffuse point
    CHECK(records > 0);
    CHECK(records * 8 < points);
}

TEST_CASE("kdpm-render refuses bad irradiance cache options in one line", "[render][irradiance-cache][cli]") {
    test::CornellBoxRuns box;
    for (const std::string bad : {"--ic-accuracy 0", "--ic-accuracy 1.5", "--ic-accuracy x", "--ic-accuracy nan",
                                  "--irradiance-cache maybe", "--gather-lookup nearest", "--gather-lookup"}) {
        const auto r = test::run_tool("kdpm-render " + box.kdg + " --mode direct " + bad + " -o " +
                                      (box.dir / "x.png").string());
        INFO(bad << ": " << r.output);
        CHECK(r.exit_code != 0);
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
        CHECK_FALSE(std::filesystem::exists(box.dir / "x.png"));
    }
}

TEST_CASE("a kept irradiance cache serves later frames and starts afresh when the gather settings change",
          "[render][final-gather][irradiance-cache]") {
    test::BuiltScene scene(800, 5, 40, 30);
    const test::InMemoryPhotons photons(scene.views.geometry, 20000, 5, 32);
    scene.views.photons = photons.maps();
    RenderSettings settings;
    settings.mode = RenderMode::final_gather;
    settings.gather_rays = 8;
    settings.light_samples = 2;
    settings.keep_irradiance_cache = true;
    Renderer renderer(scene.views, BackendKind::cpu);

    const RenderResult first = renderer.render(settings);
    REQUIRE(first.times.cache_records > 0);
    CHECK(first.times.cache_records_kept == 0);
    // The same frame again: every point is covered by the kept records, none is made, and the
    // image is the first one's (the same points read the same records).
    const RenderResult again = renderer.render(settings);
    CHECK(again.times.cache_records == 0);
    CHECK(again.times.cache_records_kept == first.times.cache_records);
    CHECK(again.linear.rgb == first.linear.rgb);
    // A moved camera keeps the records (irradiance does not depend on the view) and adds only
    // where the new view sees uncovered points.
    CameraRecord moved = scene.views.camera;
    moved.eye[0] += 0.05f;
    settings.camera = moved;
    const RenderResult elsewhere = renderer.render(settings);
    CHECK(elsewhere.times.cache_records_kept == first.times.cache_records);
    Renderer fresh_renderer(scene.views, BackendKind::cpu);
    RenderSettings fresh = settings;
    fresh.keep_irradiance_cache = false;
    CHECK(elsewhere.times.cache_records < fresh_renderer.render(fresh).times.cache_records);
    // Another accuracy makes other records: the kept ones are dropped.
    settings.ic_accuracy = 0.3f;
    const RenderResult changed = renderer.render(settings);
    CHECK(changed.times.cache_records_kept == 0);
    CHECK(changed.times.cache_records > 0);
    // Without keeping, every frame starts with an empty cache.
    settings.keep_irradiance_cache = false;
    CHECK(renderer.render(settings).times.cache_records_kept == 0);
}
