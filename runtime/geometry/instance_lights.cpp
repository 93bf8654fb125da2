#include "runtime/geometry/instance_lights.h"

#include <glm/geometric.hpp>

#include "runtime/geometry/affine.h"
#include "runtime/geometry/triangle_intersect.h"
#include "formats/math_constants.h"

namespace kdpm {

AreaLightRecord placed_light(const AreaLightRecord& light, const Affine& world_from_object) {
    AreaLightRecord l = light;
    const glm::vec3 p0 = apply_point(world_from_object, to_vec3(light.p0));
    const glm::vec3 e1 = apply_vector(world_from_object, to_vec3(light.e1));
    const glm::vec3 e2 = apply_vector(world_from_object, to_vec3(light.e2));
    for (int a = 0; a < 3; ++a) l.p0[a] = p0[a], l.e1[a] = e1[a], l.e2[a] = e2[a];
    const float parallelogram = glm::length(glm::cross(e1, e2));
    l.area = light.shape == static_cast<std::uint32_t>(LightShape::triangle) ? 0.5f * parallelogram : parallelogram;
    l.power = kPi * l.area * (l.radiance[0] + l.radiance[1] + l.radiance[2]) / 3.0f;
    l.triangle = 0xffffffffu;
    return l;
}

void append_placed_lights(std::span<const GeometryView> objects, std::span<const InstancePlacement> instances,
                          std::vector<AreaLightRecord>& out) {
    for (const InstancePlacement& p : instances) {
        const GeometryView& o = objects[p.object];
        for (std::uint32_t i = 0; i < o.light_count; ++i) out.push_back(placed_light(o.lights[i], p.world_from_object));
    }
}

}  // namespace kdpm
