#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

#include "runtime/backend/thread_limit.h"
#include "runtime/photons/photon_shooter.h"
#include "tests/photons/shooting_scenes.h"

using namespace kdpm;

namespace {

// Stored flux per bounce, summed over the hits (red channel).
std::vector<double> flux_by_bounce(const ShotPhotons& shot, std::uint32_t bounces) {
    std::vector<double> flux(bounces + 1, 0.0);
    for (const auto& h : shot.hits) flux[photon_bounce(h.flags)] += h.power[0];
    return flux;
}

}  // namespace

// In a closed box of albedo rho every path hits a wall first (bounce 0 carries all of the
// emitted power P), and each diffuse bounce keeps the expected power times rho (Russian roulette
// with survival rho keeps each photon's power and thins the photons). So the flux stored at
// bounce b is P rho^b, and the sum over all stored hits is P (1 - rho^(B+1)) / (1 - rho) for a
// bounce limit B; the hits with bounce >= 1 carry P (rho - rho^(B+1)) / (1 - rho).
TEST_CASE("Stored flux in a closed diffuse box follows the geometric series of the albedo", "[photons][shoot]") {
    for (float rho : {0.5f, 0.8f}) {
        auto box = test::closed_box(rho);
        ShootOptions options;
        options.photons = 40000;
        options.max_bounces = 4;
        auto shot = shoot_photons(box.view(), options);
        const double P = shot.info.emitted_power[0];
        CHECK(P == Approx(3.14159265 * 0.04 * 10.0).epsilon(1e-5));  // pi A L of the red channel
        auto flux = flux_by_bounce(shot, options.max_bounces);
        double total = 0.0, expected_total = 0.0;
        for (std::uint32_t b = 0; b <= options.max_bounces; ++b) {
            INFO("rho " << rho << " bounce " << b);
            CHECK(flux[b] == Approx(P * std::pow(rho, b)).epsilon(0.03));
            total += flux[b];
            expected_total += P * std::pow(rho, b);
        }
        INFO("rho " << rho);
        CHECK(expected_total == Approx(P * (1 - std::pow(rho, 5)) / (1 - rho)));
        CHECK(total == Approx(expected_total).epsilon(0.01));
        CHECK(total - flux[0] == Approx(P * (rho - std::pow(rho, 5)) / (1 - rho)).epsilon(0.015));
        CHECK(flux[0] == Approx(P).epsilon(1e-3));  // every path stores its first hit
        CHECK(shot.info.caustic_count == 0);
        // Every path traces one ray per stored hit plus, when it survives the last roulette
        // before the bounce limit, nothing more: rays == stored in a closed diffuse box.
        CHECK(shot.rays == shot.hits.size());
    }
}

TEST_CASE("Photons do not depend on the thread count", "[photons][shoot]") {
    auto box = test::closed_box(0.7f, true);
    ShootOptions options;
    options.photons = 20000;
    ShotPhotons one, two;
    {
        ThreadLimit limit(1);
        one = shoot_photons(box.view(), options);
    }
    {
        ThreadLimit limit(2);
        two = shoot_photons(box.view(), options);
    }
    REQUIRE(one.hits.size() == two.hits.size());
    CHECK(std::memcmp(one.hits.data(), two.hits.data(), one.hits.size() * sizeof(PhotonHit)) == 0);
    CHECK(std::memcmp(&one.info, &two.info, sizeof(PhotonHitsInfo)) == 0);
    options.seed = 1;
    auto other = shoot_photons(box.view(), options);
    CHECK(std::memcmp(other.hits.data(), one.hits.data(), sizeof(PhotonHit) * 4) != 0);
}

// A small light facing down at height h over an infinite floor: with cosine emission the
// fraction of photons landing within radius R of the point below is sin^2 theta = R^2 / (R^2 + h^2),
// and the cosine at arrival averages 2/3.
TEST_CASE("Emission is cosine-distributed about the light normal", "[photons][shoot]") {
    const float h = 1.0f;
    auto scene = test::floor_under_small_light(h);
    ShootOptions options;
    options.photons = 40000;
    auto shot = shoot_photons(scene.view(), options);
    REQUIRE(shot.hits.size() > 39000);  // the few that graze past the floor's edge are lost
    double mean_cos = 0.0;
    for (const auto& h : shot.hits) {
        CHECK(photon_bounce(h.flags) == 0);
        mean_cos += -h.direction[1];
    }
    CHECK(mean_cos / shot.hits.size() == Approx(2.0 / 3.0).epsilon(0.01));
    for (float R : {0.5f, 1.0f, 2.0f}) {
        std::size_t inside = 0;
        for (const auto& p : shot.hits)
            inside += p.position[0] * p.position[0] + p.position[2] * p.position[2] < R * R;
        INFO("R " << R);
        CHECK(static_cast<double>(inside) / options.photons == Approx(R * R / (R * R + h * h)).margin(0.01));
    }
}

TEST_CASE("Photons reflected by a mirror are flagged caustic and never stored on it", "[photons][shoot]") {
    auto box = test::closed_box(0.6f, true);
    ShootOptions options;
    options.photons = 20000;
    auto shot = shoot_photons(box.view(), options);
    std::uint32_t caustic = 0;
    for (const auto& h : shot.hits) {
        REQUIRE_FALSE((h.position[1] < 1e-4f && h.normal[1] > 0.5f));  // nothing on the mirror floor
        if (h.flags & kPhotonCaustic) {
            ++caustic;
            CHECK(photon_bounce(h.flags) >= 1);
        }
    }
    CHECK(caustic == shot.info.caustic_count);
    // About half of the light goes straight down onto the mirror, and all of that returns as caustics.
    CHECK(caustic > shot.info.emitted_count / 4);
}

// Lights are chosen in proportion to their power, so every emitted photon carries the same
// power (total / N) whichever light it left, and the brighter light sends three times as many.
TEST_CASE("Lights are chosen in proportion to their power", "[photons][shoot]") {
    auto box = test::closed_box_two_lights(0.5f);
    ShootOptions options;
    options.photons = 40000;
    options.max_bounces = 0;
    auto shot = shoot_photons(box.view(), options);
    const double each = shot.info.emitted_power[0] / options.photons;
    CHECK(shot.info.emitted_power[0] == Approx(3.14159265 * (0.04 * 1.0 + 0.01 * 12.0)).epsilon(1e-5));
    REQUIRE(shot.hits.size() == options.photons);  // closed box, direct hits only
    std::size_t up = 0;
    for (const auto& h : shot.hits) {
        REQUIRE(h.power[0] == Approx(each).epsilon(1e-5));
        up += h.direction[1] > 0.0f;  // the dim light faces down, the bright one up
    }
    const double down = static_cast<double>(shot.hits.size() - up);
    CHECK(up / down == Approx(3.0).epsilon(0.05));
}
