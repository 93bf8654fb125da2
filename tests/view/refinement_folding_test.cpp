#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include "runtime/render/renderer.h"
#include "runtime/view/refinement_folding.h"
#include "runtime/view/refinement_schedule.h"
#include "tests/view/lit_floor_scene.h"

using namespace kdpm;

namespace {

// The floor's edges in view (so that the camera's jitter matters) and an area light (so that
// each sample's shadow rays differ).
test::HandBuiltScene lit_floor() { return test::lit_floor(2.2f, 24); }

RenderSettings frame(RenderMode mode, std::uint32_t first, std::uint32_t spp, std::uint32_t sequence) {
    RenderSettings s;
    s.mode = mode;
    s.light_samples = 2;
    s.first_sample = first;
    s.spp = spp;
    s.sequence_spp = sequence;
    return s;
}

float largest_difference(const Image& a, const Image& b) {
    REQUIRE(a.rgb.size() == b.rgb.size());
    float d = 0.0f;
    for (std::size_t i = 0; i < a.rgb.size(); ++i) d = std::max(d, std::abs(a.rgb[i] - b.rgb[i]));
    return d;
}

}  // namespace

TEST_CASE("fold_samples weights each image by its samples", "[view][refinement]") {
    Image before(2, 1), added(2, 1);
    std::fill(before.rgb.begin(), before.rgb.end(), 1.0f);
    std::fill(added.rgb.begin(), added.rgb.end(), 5.0f);
    fold_samples(before, 3, added, 1);
    for (float v : added.rgb) CHECK(v == Approx(2.0f));
    Image other(1, 1);
    CHECK_THROWS_AS(fold_samples(other, 1, added, 1), std::invalid_argument);
}

TEST_CASE("a refinement resumed in parts averages to one render of every sample", "[view][refinement]") {
    auto scene = lit_floor();
    Renderer renderer(scene.views(), BackendKind::cpu);
    for (RenderMode mode : {RenderMode::direct, RenderMode::path}) {
        CAPTURE(render_mode_name(mode));
        // The viewer's steps up to 4 samples: samples {0}, {1}, {2, 3}, each folded into the last.
        RefinementSchedule schedule(24, 24, 4, 1);
        schedule.restart(false);
        std::optional<FinishedFrame> shown;
        std::uint32_t shown_samples = 0;
        std::uint64_t generation = 7;
        while (auto step = schedule.current()) {
            FinishedFrame f;
            f.job.generation = generation;
            f.job.settings = frame(mode, step->first_sample, step->new_samples(), step->sequence_spp);
            f.result = renderer.render(f.job.settings);
            shown_samples = fold_refinement(f, shown ? &*shown : nullptr, shown_samples);
            shown = std::move(f);
            schedule.advance();
        }
        REQUIRE(shown_samples == 4);
        const RenderResult whole = renderer.render(frame(mode, 0, 4, 0));
        // The same samples summed in another order: equal to float rounding.
        CHECK(largest_difference(shown->result.linear, whole.linear) < 1e-5f);
        CHECK(largest_difference(shown->result.display, whole.display) < 1e-5f);
        // Not trivially so: the parts differ from each other, and a fresh 1-sample frame (pixel
        // centres) is not the first sample of the jittered run.
        const RenderResult first = renderer.render(frame(mode, 0, 1, 4));
        const RenderResult centre = renderer.render(frame(mode, 0, 1, 0));
        CHECK(largest_difference(first.linear, whole.linear) > 1e-3f);
        CHECK(largest_difference(first.linear, centre.linear) > 1e-3f);
    }
}

TEST_CASE("a frame that does not continue the shown one is not folded", "[view][refinement]") {
    auto scene = lit_floor();
    Renderer renderer(scene.views(), BackendKind::cpu);
    FinishedFrame shown;
    shown.job.generation = 1;
    shown.job.settings = frame(RenderMode::direct, 0, 1, 4);
    shown.result = renderer.render(shown.job.settings);
    auto next = [&](std::uint64_t generation, std::uint32_t first) {
        FinishedFrame f;
        f.job.generation = generation;
        f.job.settings = frame(RenderMode::direct, first, 1, 4);
        f.result = renderer.render(f.job.settings);
        return f;
    };
    FinishedFrame other_view = next(2, 1);
    const Image own = other_view.result.linear;
    CHECK(fold_refinement(other_view, &shown, 1) == 1);
    CHECK(other_view.result.linear.rgb == own.rgb);
    FinishedFrame gap = next(1, 2);  // sample 1 was never shown
    CHECK(fold_refinement(gap, &shown, 1) == 1);
    FinishedFrame follows = next(1, 1);
    CHECK(fold_refinement(follows, &shown, 1) == 2);
    FinishedFrame first_frame = next(1, 1);
    CHECK(fold_refinement(first_frame, nullptr, 0) == 1);
}

TEST_CASE("samples outside their run are refused", "[view][refinement]") {
    auto scene = lit_floor();
    Renderer renderer(scene.views(), BackendKind::cpu);
    CHECK_THROWS_WITH(renderer.render(frame(RenderMode::direct, 3, 2, 4)), Catch::Contains("outside a run of 4"));
    CHECK_THROWS_WITH(renderer.render(frame(RenderMode::direct, std::numeric_limits<std::uint32_t>::max(), 1, 0)),
                      Catch::Contains("too many"));
    RenderSettings sppm = frame(RenderMode::sppm, 1, 1, 4);
    CHECK_THROWS_WITH(renderer.render(sppm), Catch::Contains("sppm"));
}
