#pragma once
// The area lights of a scene of instances in world space: each placed object's lights mapped by
// its instance (recomputed whenever placements change), so that light sampling and photon
// emission see one flat list as in a scene of one mesh.
#include <span>
#include <vector>

#include "formats/geometry_layout.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/instance_view.h"

namespace kdpm {

// An object's light under a map: corner and edges mapped, area and emission power recomputed
// (a scaled instance emits over its scaled area). It names no triangle of the scene's.
AreaLightRecord placed_light(const AreaLightRecord& light, const Affine& world_from_object);

// Appends, instance by instance, the placed lights of every instance's object.
void append_placed_lights(std::span<const GeometryView> objects, std::span<const InstancePlacement> instances,
                          std::vector<AreaLightRecord>& out);

}  // namespace kdpm
