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

// Outgoing radiance at point x (unit normal n facing the viewer, diffuse albedo) due to direct
// light: albedo / pi * sum over lights of the estimated irradiance. `samples` per light are
// stratified on a grid (rounded up to a square), jittered by (seed, stream).
KDPM_HD KDPM_INLINE glm::vec3 direct_light(const GeometryView& g, const glm::vec3& x, const glm::vec3& n,
                                           const glm::vec3& albedo, std::uint32_t samples, float epsilon,
                                           std::uint32_t seed, std::uint32_t stream) {
    glm::vec3 irradiance(0.0f);
    std::uint32_t side = 1;
    while (side * side < samples) ++side;
    const float inv_n = 1.0f / static_cast<float>(side * side);
    const glm::vec3 origin = x + epsilon * n;
    for (std::uint32_t li = 0; li < g.light_count; ++li) {
        const AreaLightRecord& l = g.lights[li];
        const glm::vec3 e1(l.e1[0], l.e1[1], l.e1[2]);
        const glm::vec3 e2(l.e2[0], l.e2[1], l.e2[2]);
        const glm::vec3 light_n = glm::normalize(glm::cross(e1, e2));
        const glm::vec3 radiance(l.radiance[0], l.radiance[1], l.radiance[2]);
        glm::vec3 sum(0.0f);
        for (std::uint32_t j = 0; j < side * side; ++j) {
            const float a = (static_cast<float>(j % side) + random01(seed, stream * 131u + li, 2u * j)) / side;
            const float b = (static_cast<float>(j / side) + random01(seed, stream * 131u + li, 2u * j + 1u)) / side;
            const glm::vec3 y = point_on_light(l, a, b);
            const glm::vec3 d = y - origin;
            const float dist2 = glm::dot(d, d);
            if (!(dist2 > 0.0f)) continue;
            const glm::vec3 wi = d / glm::sqrt(dist2);
            const float cos_x = glm::dot(n, wi);
            const float cos_y = -glm::dot(light_n, wi);
            if (cos_x <= 0.0f || cos_y <= 0.0f) continue;
            // The segment stops just short of the light, which may itself be scene geometry.
            Ray shadow{origin, 0.0f, d, 1.0f - 1e-4f};
            if (occluded(g, shadow)) continue;
            sum += radiance * (cos_x * cos_y / dist2);
        }
        irradiance += sum * (l.area * inv_n);
    }
    return albedo * (1.0f / 3.14159265358979f) * irradiance;
}

}  // namespace kdpm
