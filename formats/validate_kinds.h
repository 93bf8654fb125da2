#pragma once
// One structural validator per file kind (a photon tree file's as separate passes); each lives in
// its own validate_*.cpp.
#include <functional>
#include <vector>

#include "formats/container_reader.h"
#include "formats/tree_validation.h"

namespace kdpm {

void validate_geometry_file(const ContainerReader& file, const ValidationOptions& options);
void validate_photon_hits_file(const ContainerReader& file, const ValidationOptions& options);

// A photon tree file's checks as independent passes (each map's tree, the irradiance map's own
// sections), in the order their failures are reported; validate_file may run them on two threads.
// Every pass takes any bytes and relies on no other pass having succeeded.
std::vector<std::function<void()>> photon_tree_passes(const ContainerReader& file, const ValidationOptions& options);

}  // namespace kdpm
