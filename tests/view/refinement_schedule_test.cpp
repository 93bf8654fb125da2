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
    s.advance();
    std::vector<std::uint32_t> spp;
    while (auto st = s.current()) {
        CHECK_FALSE(st->preview);
        CHECK(st->width == 512);
        CHECK(st->height == 256);
        spp.push_back(st->spp);
        s.advance();
    }
    CHECK(spp == std::vector<std::uint32_t>{1, 2, 4, 6});
    // A change starts over; without a preview it begins at full resolution.
    s.restart(false);
    REQUIRE(s.current());
    CHECK_FALSE(s.current()->preview);
    CHECK(s.current()->spp == 1);
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
