#pragma once
// One structural validator per file kind (a photon tree file's as separate passes); each lives in
// its own validate_*.cpp.
#include <functional>
#include <vector>

#include "formats/container_reader.h"
#include "formats/geometry_layout.h"
#include "formats/tree_validation.h"

namespace kdpm {

void validate_geometry_file(const ContainerReader& file, const ValidationOptions& options);
// A .kdg of instances (format 1.3): the objects it places, the placements, its camera and lights;
// the object files themselves are checked when the runtime opens them.
void validate_instanced_scene_file(const ContainerReader& file, const ValidationOptions& options);
void validate_photon_hits_file(const ContainerReader& file, const ValidationOptions& options);

// Shared by both geometry validators: the card's defaults and the bounds in geometry.info, and
// the area lights (a light may name one of the file's tri_count triangles).
void check_scene_defaults(const ContainerReader& file, const GeometryInfo& info);
void check_lights(const ContainerReader& file, std::span<const AreaLightRecord> lights, std::size_t tri_count);

// A photon tree file's checks as independent passes (each map's tree, the irradiance map's own
// sections), in the order their failures are reported; validate_file may run them on two threads.
// Every pass takes any bytes and relies on no other pass having succeeded.
std::vector<std::function<void()>> photon_tree_passes(const ContainerReader& file, const ValidationOptions& options);

}  // namespace kdpm
