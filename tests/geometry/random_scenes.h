#pragma once
// Random triangle soups and rays for the geometry tests (fixed seeds: reproducible).
#include <cstdint>
#include <random>
#include <vector>

#include "builders/geometry/scene.h"
#include "runtime/geometry/ray.h"

namespace kdpm::test {

// n triangles with vertices near random centres in [0, 1]^3, sizes up to `size`.
inline std::vector<TriangleRecord> random_soup(std::uint32_t n, std::uint32_t seed, float size = 0.1f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f), d(-size, size);
    std::vector<TriangleRecord> tris;
    for (std::uint32_t i = 0; i < n; ++i) {
        float c[3] = {u(rng), u(rng), u(rng)}, a[3], b[3], e[3];
        for (int k = 0; k < 3; ++k) a[k] = c[k] + d(rng), b[k] = c[k] + d(rng), e[k] = c[k] + d(rng);
        tris.push_back(make_triangle(a, b, e, 0, i));
    }
    return tris;
}

// Axis-aligned triangles on an 8 x 8 grid in z = 0.5 and in y = 0.25, whose kd split planes lie
// at exact coordinates (rays can start on them), with a random soup beside. With twins, each
// z = 0.5 triangle is followed by a twin that differs only in the sign of a zero (no exact copy,
// which the builder drops): every ray that hits one hits both at the same t, a tie the single-ray
// walk breaks by test order.
inline std::vector<TriangleRecord> grid_scene(bool with_twins) {
    std::vector<TriangleRecord> tris;
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 8; ++j) {
            const float x = static_cast<float>(i) * 0.125f, y = static_cast<float>(j) * 0.125f;
            const float a[3] = {x, y, 0.5f}, b[3] = {x + 0.125f, y, 0.5f}, c[3] = {x, y + 0.125f, 0.5f};
            tris.push_back(make_triangle(a, b, c, 0, static_cast<std::uint32_t>(tris.size())));
            if (with_twins) {
                TriangleRecord twin = tris.back();
                twin.e1[2] = -0.0f;
                twin.source_index = static_cast<std::uint32_t>(tris.size());
                tris.push_back(twin);
            }
            const float d[3] = {x, 0.25f, y}, e[3] = {x + 0.125f, 0.25f, y}, f[3] = {x, 0.25f, y + 0.125f};
            tris.push_back(make_triangle(d, e, f, 0, static_cast<std::uint32_t>(tris.size())));
        }
    const auto soup = random_soup(400, 5, 0.05f);
    tris.insert(tris.end(), soup.begin(), soup.end());
    return tris;
}

// Rays from random points in a box slightly larger than [lo, hi] towards random directions.
inline std::vector<Ray> random_rays(std::uint32_t n, std::uint32_t seed, float lo = -0.2f, float hi = 1.2f) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(lo, hi);
    std::normal_distribution<float> g(0.0f, 1.0f);
    std::vector<Ray> rays;
    for (std::uint32_t i = 0; i < n; ++i) {
        glm::vec3 dir(g(rng), g(rng), g(rng));
        rays.push_back(Ray{glm::vec3(u(rng), u(rng), u(rng)), 0.0f, dir, 1e30f});
    }
    return rays;
}

}  // namespace kdpm::test
