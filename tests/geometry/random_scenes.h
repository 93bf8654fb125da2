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
