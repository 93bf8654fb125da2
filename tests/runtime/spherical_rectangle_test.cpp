// Solid-angle sampling of rectangle lights against closed forms: the subtended solid angle
// (Van Oosterom & Strackee), points on the rectangle, the irradiance estimate's mean (Lambert's
// polygon formula), and a bounded variance where area sampling has none: a point close to the
// light and nearly in its plane.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "runtime/shading/spherical_rectangle.h"

using namespace kdpm;

namespace {

double triangle_solid_angle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double num = std::fabs(glm::dot(a, glm::cross(b, c)));
    const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return 2.0 * std::atan2(num, den);
}

double rectangle_solid_angle(glm::dvec3 x, glm::dvec3 p0, glm::dvec3 e1, glm::dvec3 e2) {
    const glm::dvec3 a = p0 - x, b = p0 + e1 - x, c = p0 + e1 + e2 - x, d = p0 + e2 - x;
    return triangle_solid_angle(a, b, c) + triangle_solid_angle(a, c, d);
}

// Lambert: E / L = 1/2 sum_i angle(r_i, r_i+1) n . unit(r_i x r_i+1), for a polygon wholly above x's plane.
double polygon_irradiance(const std::vector<glm::dvec3>& corners, glm::dvec3 x, glm::dvec3 n) {
    double sum = 0;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        glm::dvec3 a = glm::normalize(corners[i] - x), b = glm::normalize(corners[(i + 1) % corners.size()] - x);
        sum += std::acos(glm::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
    }
    return 0.5 * std::fabs(sum);
}

struct Estimate {
    double mean = 0, relative_std = 0;
};

// The irradiance estimate L cos_x S (L = 1) over n x n stratified samples, repeated with jitter.
Estimate estimate(const SphericalRectangle& q, glm::vec3 x, glm::vec3 normal, int n, int repeats, std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::vector<double> values;
    for (int r = 0; r < repeats; ++r) {
        double sum = 0;
        for (int i = 0; i < n * n; ++i) {
            const glm::vec3 p = q.point((static_cast<float>(i % n) + unit(rng)) / n, (static_cast<float>(i / n) + unit(rng)) / n);
            const float c = glm::dot(normal, glm::normalize(p - x));
            sum += c > 0.0f ? c * q.solid_angle : 0.0;
        }
        values.push_back(sum / (n * n));
    }
    Estimate e;
    for (double v : values) e.mean += v;
    e.mean /= repeats;
    double var = 0;
    for (double v : values) var += (v - e.mean) * (v - e.mean);
    e.relative_std = std::sqrt(var / repeats) / e.mean;
    return e;
}

}  // namespace

TEST_CASE("a spherical rectangle subtends the solid angle of its rectangle, its points lie on it, and its "
          "irradiance estimate is Lambert's",
          "[render][lights]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int checked = 0;
    for (int trial = 0; trial < 200; ++trial) {
        // A random rectangle (perpendicular edges) and a point on either side of it.
        const glm::vec3 p0(u(rng), u(rng), u(rng));
        glm::vec3 a = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
        glm::vec3 b = glm::normalize(glm::cross(a, glm::vec3(u(rng), u(rng), u(rng))));
        const glm::vec3 e1 = a * (0.2f + 2.0f * std::fabs(u(rng))), e2 = b * (0.2f + 2.0f * std::fabs(u(rng)));
        const glm::vec3 x = glm::vec3(u(rng), u(rng), u(rng)) * 2.0f;
        SphericalRectangle q;
        if (!spherical_rectangle(x, p0, e1, e2, q)) continue;
        if (q.solid_angle < 0.02f) continue;  // the renderer samples such ones by area
        const double expected = rectangle_solid_angle(x, p0, e1, e2);
        INFO("trial " << trial);
        CHECK(q.solid_angle == Approx(expected).epsilon(1e-3));
        const glm::vec3 n = glm::normalize(glm::cross(e1, e2));
        for (int s = 0; s < 16; ++s) {
            const glm::vec3 p = q.point((s % 4 + 0.5f) / 4.0f, (s / 4 + 0.5f) / 4.0f);
            const glm::vec3 d = p - p0;
            CHECK(std::fabs(glm::dot(d, n)) < 1e-4f);  // in the plane
            CHECK(glm::dot(d, e1) / glm::dot(e1, e1) == Approx(0.5).margin(0.5001));
            CHECK(glm::dot(d, e2) / glm::dot(e2, e2) == Approx(0.5).margin(0.5001));
        }
        // The irradiance on a surface facing the rectangle's centre, when the whole rectangle is
        // above that surface (Lambert's formula needs no clipping then).
        const glm::vec3 centre = p0 + 0.5f * e1 + 0.5f * e2;
        const glm::vec3 facing = glm::normalize(centre - x);
        bool above = true;
        for (glm::vec3 c : {p0, p0 + e1, p0 + e2, p0 + e1 + e2}) above = above && glm::dot(c - x, facing) > 0.05f;
        if (!above) continue;
        const std::vector<glm::dvec3> corners{glm::dvec3(p0), glm::dvec3(p0 + e1), glm::dvec3(p0 + e1 + e2), glm::dvec3(p0 + e2)};
        const Estimate e = estimate(q, x, facing, 16, 4, rng);
        CHECK(e.mean == Approx(polygon_irradiance(corners, glm::dvec3(x), glm::dvec3(facing))).epsilon(0.01));
        ++checked;
    }
    CHECK(checked > 50);
}

TEST_CASE("solid-angle sampling keeps a point beside a large light, nearly in its plane, free of fireflies",
          "[render][lights]") {
    // A 20 x 6 sky facing down at y = 1; the point 1 cm below its plane, 2 cm outside its edge,
    // on a wall facing the region under the light. By area, the nearest strip of the light
    // weighs cos_y / d^2 ~ 10^2 times the rest: 16 samples vary by far more than their mean.
    const glm::vec3 p0(-10, 1, 0), e1(20, 0, 0), e2(0, 0, 6);
    const glm::vec3 x(0.0f, 0.99f, -0.02f), normal(0, 0, 1);
    SphericalRectangle q;
    REQUIRE(spherical_rectangle(x, p0, e1, e2, q));
    std::mt19937 rng(5);
    const Estimate e = estimate(q, x, normal, 4, 400, rng);
    const std::vector<glm::dvec3> corners{glm::dvec3(p0), glm::dvec3(p0 + e1), glm::dvec3(p0 + e1 + e2), glm::dvec3(p0 + e2)};
    INFO("mean " << e.mean << ", relative std of 16 samples " << e.relative_std);
    CHECK(e.mean == Approx(polygon_irradiance(corners, glm::dvec3(x), glm::dvec3(normal))).epsilon(0.01));
    CHECK(e.relative_std < 0.1);
}
