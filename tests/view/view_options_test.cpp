#include <catch2/catch.hpp>

#include "runtime/view/view_options.h"

using namespace kdpm;

TEST_CASE("view options keep k within the estimate's range (that of kdpm-render's --k) when halving and doubling", "[view][options]") {
    ViewOptions o;
    o.k = 64;
    o.double_k();
    CHECK(o.k == 128);
    o.double_k();
    o.double_k();
    CHECK(o.k == 256);
    o.k = 3;
    o.halve_k();
    CHECK(o.k == 1);
    o.halve_k();
    CHECK(o.k == 1);
    CHECK(clamp_k(0) == 1);
    CHECK(clamp_k(1000) == 256);
    CHECK(ViewOptions::kMinK == kMinEstimateK);
    CHECK(ViewOptions::kMaxK == kMaxEstimateK);
}

TEST_CASE("view options offer photon modes and the density view only with a photon map", "[view][options]") {
    ViewOptions o;
    o.mode = RenderMode::direct;
    o.next_mode(false);
    CHECK(o.mode == RenderMode::direct);
    o.next_mode(true);
    CHECK(o.mode == RenderMode::photons);
    o.next_mode(true);
    CHECK(o.mode == RenderMode::direct_photons);
    o.next_mode(true);
    CHECK(o.mode == RenderMode::direct);
    // The slow modes are chosen in the panel; the key leaves them for the cycle's next mode.
    for (RenderMode slow : {RenderMode::path, RenderMode::sppm, RenderMode::final_gather}) {
        o.mode = slow;
        o.next_mode(true);
        CHECK(o.mode == RenderMode::photons);
        o.mode = slow;
        o.next_mode(false);
        CHECK(o.mode == RenderMode::direct);
    }
    CHECK(key_help_text().find("photons / direct+photons / direct") != std::string::npos);

    o.view = ViewKind::shaded;
    o.next_view(false);
    o.next_view(false);
    CHECK(o.view == ViewKind::normal);
    o.next_view(false);
    CHECK(o.view == ViewKind::shaded);
    o.view = ViewKind::normal;
    o.next_view(true);
    CHECK(o.view == ViewKind::photon_density);
    o.next_view(true);
    CHECK(o.view == ViewKind::shaded);
}

TEST_CASE("view options cycle tone mappers and bound the exposure", "[view][options]") {
    ViewOptions o;
    o.next_tone_map();
    CHECK(o.tone_map == ToneMap::reinhard);
    o.next_tone_map();
    CHECK(o.tone_map == ToneMap::none);
    o.next_tone_map();
    CHECK(o.tone_map == ToneMap::aces);
    for (int i = 0; i < 200; ++i) o.brighter();
    CHECK(o.exposure_stops == kMaxExposureStops);
    o.darker();
    CHECK(o.exposure_stops == kMaxExposureStops - 0.5f);
    for (int i = 0; i < 200; ++i) o.darker();
    CHECK(o.exposure_stops == -kMaxExposureStops);
    CHECK(parse_view("density") == ViewKind::photon_density);
    CHECK_THROWS_AS(parse_view("sideways"), std::invalid_argument);
    CHECK(key_help_text().find("F12") != std::string::npos);
}

TEST_CASE("each view asks only for the AOVs it shows, and a switch renders anew when those differ",
          "[view][options]") {
    CHECK_FALSE(aovs_for_view(ViewKind::shaded).any());
    const AovSet depth = aovs_for_view(ViewKind::depth), normal = aovs_for_view(ViewKind::normal),
                 density = aovs_for_view(ViewKind::photon_density);
    CHECK((depth.depth && !depth.normal && !depth.position));
    CHECK((normal.normal && !normal.depth && !normal.position));
    CHECK((density.position && density.normal && !density.depth));
    const ViewKind views[] = {ViewKind::shaded, ViewKind::depth, ViewKind::normal, ViewKind::photon_density};
    for (ViewKind from : views) {
        CHECK_FALSE(view_switch_renders(from, from));
        for (ViewKind to : views)
            if (to != from) CHECK(view_switch_renders(from, to));  // no two views need the same frame
    }
}
