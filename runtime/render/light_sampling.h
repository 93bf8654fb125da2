#pragma once
// Direct light from the area lights at a diffuse point, by shadow rays to stratified points on
// each light (Monte Carlo estimate of the irradiance integral; one-sided emitters).
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/kd_traversal.h"
#include "runtime/render/counter_random.h"

namespace kdpm {

// A point on the light for the unit square sample (a, b): uniform over its area.
KDPM_HD KDPM_INLINE glm::vec3 point_on_light(const AreaLightRecord& l, float a, float b) {
    const glm::vec3 p0(l.p0[0], l.p0[1], l.p0[2]);
    const glm::vec3 e1(l.e1[0], l.e1[1], l.e1[2]);
    const glm::vec3 e2(l.e2[0], l.e2[1], l.e2[2]);
    if (l.shape == static_cast<std::uint32_t>(LightShape::triangle)) {
        const float s = glm::sqrt(a);  // uniform triangle sampling by the square-root warp
        return p0 + s * (1.0f - b) * e1 + s * b * e2;
    }
    return p0 + a * e1 + b * e2;
}

// The lights as a discrete distribution by emitted power: cdf[i] = sum of power[0..i] / total.
struct LightDistributionView {
    const float* cdf = nullptr;  // one per light; nullptr or count 0: no light emits
    std::uint32_t count = 0;
};

// Index i with cdf[i-1] <= u < cdf[i] (binary search), and its probability.
KDPM_HD KDPM_INLINE std::uint32_t pick_light(const LightDistributionView& d, float u, float& probability) {
    std::uint32_t lo = 0, hi = d.count - 1;
    while (lo < hi) {
        const std::uint32_t mid = (lo + hi) / 2;
        if (u < d.cdf[mid]) hi = mid;
        else lo = mid + 1;
    }
    probability = d.cdf[lo] - (lo > 0 ? d.cdf[lo - 1] : 0.0f);
    return lo;
}

// Outgoing radiance at point x (unit normal n facing the viewer, diffuse albedo) due to direct
// light: albedo / pi times the irradiance, estimated with `samples` shadow rays (rounded up to a
// square). Each ray picks a light by power, then a point on it, so scenes with many emitting
// triangles cost no more per ray.
// `origin` is x already offset off the surface.
KDPM_HD KDPM_INLINE glm::vec3 direct_light(const GeometryView& g, const LightDistributionView& lights,
                                           const glm::vec3& origin, const glm::vec3& n, const glm::vec3& albedo,
                                           std::uint32_t samples, std::uint32_t seed, std::uint32_t stream) {
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
        const float u = single ? 0.0f : (static_cast<float>(j) + random01(seed, stream, 3u * j)) / total;
        float probability = 0.0f;
        const std::uint32_t li = pick_light(lights, u, probability);
        if (!(probability > 0.0f)) continue;
        const AreaLightRecord& l = g.lights[li];
        const float ra = random01(seed, stream, 3u * j + 1u), rb = random01(seed, stream, 3u * j + 2u);
        const float a = single ? (static_cast<float>(j % side) + ra) / side : ra;
        const float b = single ? (static_cast<float>(j / side) + rb) / side : rb;
        const glm::vec3 e1(l.e1[0], l.e1[1], l.e1[2]);
        const glm::vec3 e2(l.e2[0], l.e2[1], l.e2[2]);
        const glm::vec3 light_n = glm::normalize(glm::cross(e1, e2));
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
        const glm::vec3 radiance(l.radiance[0], l.radiance[1], l.radiance[2]);
        irradiance += radiance * (cos_x * cos_y / dist2 * l.area / probability);
    }
    return albedo * (1.0f / 3.14159265358979f) * irradiance / static_cast<float>(total);
}

}  // namespace kdpm
