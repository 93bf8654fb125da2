#pragma once
// Direct light from the area lights at a diffuse point, by shadow rays to stratified points on
// the lights (Monte Carlo estimate of the irradiance integral; one-sided emitters): uniform in
// the solid angle for rectangles (spherical_rectangle.h), uniform in area otherwise.
#include <cstdint>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "formats/geometry_layout.h"
#include "formats/host_device.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/kd_packet_traversal.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/shading/area_light.h"
#include "runtime/shading/counter_random.h"
#include "runtime/shading/diffuse.h"
#include "runtime/shading/spherical_rectangle.h"

namespace kdpm {

// Rectangles seen under less than this are sampled by area: far away both ways are alike, and
// the spherical rectangle's angles lose float precision as it shrinks.
inline constexpr float kMinSampledSolidAngle = 0.02f;

// A card light whose edges are perpendicular (within float noise): sampled in solid angle.
KDPM_HD KDPM_INLINE bool is_rectangle(const AreaLightRecord& l) {
    if (l.shape != static_cast<std::uint32_t>(LightShape::parallelogram)) return false;
    const glm::vec3 e1 = to_vec3(l.e1), e2 = to_vec3(l.e2);
    return fabsf(glm::dot(e1, e2)) <= 1e-4f * glm::length(e1) * glm::length(e2);
}

// Which light a shadow ray goes to: by power for u below 0.9, uniformly above. By power alone a
// dim emitter right beside the point (the Conference room's exit sign on its wall) is picked with
// a probability of ~1e-5 and then weighs 1e5: one such ray made 74 % of a 4-spp frame's error.
// The uniform share bounds every light's weight by 10 x the light count; a tenth of the rays
// going by count instead of power is what it costs where lights differ in power.
inline constexpr float kUniformLightShare = 0.1f;

KDPM_HD KDPM_INLINE std::uint32_t pick_shadow_light(const LightSelection& lights, float u) {
    constexpr float by_power = 1.0f - kUniformLightShare;
    if (u < by_power) return pick_light(lights, u / by_power);
    const float at = (u - by_power) / kUniformLightShare * static_cast<float>(lights.count);
    const std::uint32_t i = static_cast<std::uint32_t>(at);
    return i < lights.count ? i : lights.count - 1;
}

KDPM_HD KDPM_INLINE float shadow_light_probability(const LightSelection& lights, std::uint32_t i) {
    if (lights.count == 1) return pick_probability(lights, i);
    return (1.0f - kUniformLightShare) * pick_probability(lights, i) +
           kUniformLightShare / static_cast<float>(lights.count);
}

// The spherical rectangle of the last light sampled from one point (one memo per point): its
// set-up (four normalizations, four arc cosines) depends only on the point and the light, and
// the shadow rays of a point mostly pick the same light (always, with one).
struct LightFrameMemo {
    std::uint32_t light = 0xffffffffu;
    bool in_solid_angle = false;
    SphericalRectangle q;
};

// Shadow ray j of direct_light_with and the irradiance it brings if unoccluded; false where the
// sample brings none whatever lies between (no light picked, the light behind x or facing away).
template <class Random>
KDPM_HD KDPM_INLINE bool light_sample(const GeometryView& g, const LightSelection& lights, const glm::vec3& origin,
                                      const glm::vec3& n, std::uint32_t j, std::uint32_t side, const Random& random,
                                      Ray& shadow, glm::vec3& irradiance, LightFrameMemo* memo = nullptr) {
    const std::uint32_t total = side * side;
    // One light: its area is stratified on the grid. Several: the choice of light is
    // stratified instead (the point on it is then uniform, so that it stays independent of
    // the choice).
    const bool single = lights.count == 1;
    const float u = single ? 0.0f : (static_cast<float>(j) + random(3u * j)) / total;
    const std::uint32_t li = pick_shadow_light(lights, u);
    const float probability = shadow_light_probability(lights, li);
    if (!(probability > 0.0f)) return false;
    const AreaLightRecord& l = g.lights[li];
    const float ra = random(3u * j + 1u), rb = random(3u * j + 2u);
    const float a = single ? (static_cast<float>(j % side) + ra) / side : ra;
    const float b = single ? (static_cast<float>(j / side) + rb) / side : rb;
    const glm::vec3 light_n = light_normal(l);
    LightFrameMemo local;
    LightFrameMemo& m = memo ? *memo : local;
    if (m.light != li) {
        m.light = li;
        m.in_solid_angle = is_rectangle(l) && glm::dot(origin - to_vec3(l.p0), light_n) > 0.0f &&
                           spherical_rectangle(origin, to_vec3(l.p0), to_vec3(l.e1), to_vec3(l.e2), m.q) &&
                           m.q.solid_angle > kMinSampledSolidAngle;
    }
    const bool in_solid_angle = m.in_solid_angle;
    const SphericalRectangle& q = m.q;
    const glm::vec3 d = (in_solid_angle ? q.point(a, b) : point_on_light(l, a, b)) - origin;
    const float dist2 = glm::dot(d, d);
    if (!(dist2 > 0.0f)) return false;
    const glm::vec3 wi = d / glm::sqrt(dist2);
    const float cos_x = glm::dot(n, wi);
    const float cos_y = -glm::dot(light_n, wi);
    if (cos_x <= 0.0f || cos_y <= 0.0f) return false;
    // The segment stops just short of the light, which may itself be scene geometry.
    shadow = Ray{origin, 0.0f, d, 1.0f - 1e-4f};
    // Uniform in solid angle the weight is the solid angle; uniform in area, cos_y A / d^2.
    const float weight = in_solid_angle ? q.solid_angle : cos_y / dist2 * l.area;
    irradiance = to_vec3(l.radiance) * (cos_x * weight / probability);
    return true;
}

// Outgoing radiance at point x (unit normal n facing the viewer, diffuse albedo) due to direct
// light: albedo / pi times the irradiance, estimated with `samples` shadow rays (rounded up to a
// square), random(3j + 0..2) for ray j. Each ray picks a light (pick_shadow_light), then a
// point on it, so scenes with many emitting triangles cost no more per ray.
// `origin` is x already offset off the surface. `random(d)` is uniform in [0, 1) for dimension d,
// a pure function of its caller's counters (ShadingRandom below; the path tracer keys its own).
// On the CPU the shadow rays, which share their origin, are walked 16 at a time as one packet
// (kd_packet_traversal.h); the same rays are blocked and the sum runs in the same order.
template <class Random>
KDPM_HD KDPM_INLINE glm::vec3 direct_light_with(const GeometryView& g, const LightSelection& lights,
                                                const glm::vec3& origin, const glm::vec3& n, const glm::vec3& albedo,
                                                std::uint32_t samples, const Random& random) {
    if (lights.count == 0 || lights.cdf == nullptr) return glm::vec3(0.0f);
    std::uint32_t side = 1;
    while (side * side < samples) ++side;
    const std::uint32_t total = side * side;
    glm::vec3 irradiance(0.0f);
    LightFrameMemo memo;
#if defined(__CUDA_ARCH__)
    for (std::uint32_t j = 0; j < total; ++j) {
        Ray shadow;
        glm::vec3 e;
        if (light_sample(g, lights, origin, n, j, side, random, shadow, e, &memo) && !occluded(g, shadow))
            irradiance += e;
    }
#else
    for (std::uint32_t first = 0; first < total; first += kPacketRays) {
        const std::uint32_t end = total - first < kPacketRays ? total : first + kPacketRays;
        RayPacket packet;
        glm::vec3 e[kPacketRays];
        for (std::uint32_t j = first; j < end; ++j) {
            Ray shadow;
            if (light_sample(g, lights, origin, n, j, side, random, shadow, e[packet.count], &memo))
                packet.set(packet.count++, shadow);
        }
        bool blocked[kPacketRays];
        occluded_rays(g, packet, blocked);
        for (std::uint32_t i = 0; i < packet.count; ++i)
            if (!blocked[i]) irradiance += e[i];
    }
#endif
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
