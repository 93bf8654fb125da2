#include <catch2/catch.hpp>

#include <vector>

#include "runtime/view/refinement_schedule.h"

using namespace kdpm;

TEST_CASE("refinement schedule goes from a preview to full resolution with doubling spp", "[view][schedule]") {
    RefinementSchedule s(512, 256, 6, 4);
    s.restart(true);
    auto step = s.current();
    REQUIRE(step);
    CHECK(step->preview);
    CHECK(step->width == 128);
    CHECK(step->height == 64);
    CHECK(step->spp == 1);
    CHECK(step->first_sample == 0);
    CHECK(step->sequence_spp == 1);  // a preview is a run of its own: not jittered
    s.advance();
    std::vector<std::uint32_t> spp, first;
    while (auto st = s.current()) {
        CHECK_FALSE(st->preview);
        CHECK(st->width == 512);
        CHECK(st->height == 256);
        CHECK(st->sequence_spp == 6);
        spp.push_back(st->spp);
        first.push_back(st->first_sample);
        s.advance();
    }
    CHECK(spp == std::vector<std::uint32_t>{1, 2, 4, 6});
    // Each step renders only the samples the shown image lacks: six in all, not 13.
    CHECK(first == std::vector<std::uint32_t>{0, 1, 2, 4});
    // A change starts over; without a preview it begins at full resolution.
    s.restart(false);
    REQUIRE(s.current());
    CHECK_FALSE(s.current()->preview);
    CHECK(s.current()->spp == 1);
    CHECK(s.current()->first_sample == 0);
}

TEST_CASE("refinement schedule keeps tiny previews at least one pixel", "[view][schedule]") {
    RefinementSchedule s(3, 2, 1, 8);
    s.restart(true);
    CHECK(s.current()->width == 1);
    CHECK(s.current()->height == 1);
    s.advance();
    CHECK(s.current()->spp == 1);
    s.advance();
    CHECK_FALSE(s.current());
    // A divisor of 1 means no preview step.
    RefinementSchedule none(64, 64, 4, 1);
    none.restart(true);
    CHECK_FALSE(none.current()->preview);
}
