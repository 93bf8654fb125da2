#pragma once
// Direct light from the area lights at a diffuse point, by shadow rays to stratified points on
// the lights (Monte Carlo estimate of the irradiance integral; one-sided emitters).
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/kd_traversal.h"
#include "runtime/shading/area_light.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"

namespace kdpm {

// Outgoing radiance at point x (unit normal n facing the viewer, diffuse albedo) due to direct
// light: albedo / pi times the irradiance, estimated with `samples` shadow rays (rounded up to a
// square), random(3j + 0..2) for ray j. Each ray picks a light by power, then a
// point on it, so scenes with many emitting triangles cost no more per ray.
// `origin` is x already offset off the surface. `random(d)` is uniform in [0, 1) for dimension d,
// a pure function of its caller's counters (ShadingRandom below; the path tracer keys its own).
template <class Random>
KDPM_HD KDPM_INLINE glm::vec3 direct_light_with(const GeometryView& g, const LightSelection& lights,
                                                const glm::vec3& origin, const glm::vec3& n, const glm::vec3& albedo,
                                                std::uint32_t samples, const Random& random) {
    if (lights.count == 0 || lights.cdf == nullptr) return glm::vec3(0.0f);
    std::uint32_t side = 1;
    while (side * side < samples) ++side;
    const std::uint32_t total = side * side;
    glm::vec3 irradiance(0.0f);
    for (std::uint32_t j = 0; j < total; ++j) {
        // One light: its area is stratified on the grid. Several: the choice of light is
        // stratified instead (the point on it is then uniform, so that it stays independent of
        // the choice).
        const bool single = lights.count == 1;
        const float u = single ? 0.0f : (static_cast<float>(j) + random(3u * j)) / total;
        const std::uint32_t li = pick_light(lights, u);
        const float probability = pick_probability(lights, li);
        if (!(probability > 0.0f)) continue;
        const AreaLightRecord& l = g.lights[li];
        const float ra = random(3u * j + 1u), rb = random(3u * j + 2u);
        const float a = single ? (static_cast<float>(j % side) + ra) / side : ra;
        const float b = single ? (static_cast<float>(j / side) + rb) / side : rb;
        const glm::vec3 light_n = light_normal(l);
        const glm::vec3 d = point_on_light(l, a, b) - origin;
        const float dist2 = glm::dot(d, d);
        if (!(dist2 > 0.0f)) continue;
        const glm::vec3 wi = d / glm::sqrt(dist2);
        const float cos_x = glm::dot(n, wi);
        const float cos_y = -glm::dot(light_n, wi);
        if (cos_x <= 0.0f || cos_y <= 0.0f) continue;
        // The segment stops just short of the light, which may itself be scene geometry.
        const Ray shadow{origin, 0.0f, d, 1.0f - 1e-4f};
        if (occluded(g, shadow)) continue;
        irradiance += to_vec3(l.radiance) * (cos_x * cos_y / dist2 * l.area / probability);
    }
    return lambert_brdf(albedo) * irradiance / static_cast<float>(total);
}

// The camera modes' stream: random01(seed, stream, dimension).
struct ShadingRandom {
    std::uint32_t seed, stream;
    KDPM_HD float operator()(std::uint32_t dimension) const { return random01(seed, stream, dimension); }
};

KDPM_HD KDPM_INLINE glm::vec3 direct_light(const GeometryView& g, const LightSelection& lights,
                                           const glm::vec3& origin, const glm::vec3& n, const glm::vec3& albedo,
                                           std::uint32_t samples, std::uint32_t seed, std::uint32_t stream) {
    return direct_light_with(g, lights, origin, n, albedo, samples, ShadingRandom{seed, stream});
}

}  // namespace kdpm
