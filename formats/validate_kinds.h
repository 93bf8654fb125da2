#pragma once
// One structural validator per file kind; each lives in its own validate_*.cpp.
#include "formats/container_reader.h"
#include "formats/tree_validation.h"

namespace kdpm {

void validate_geometry_file(const ContainerReader& file, const ValidationOptions& options);
void validate_photon_hits_file(const ContainerReader& file, const ValidationOptions& options);
void validate_photon_tree_file(const ContainerReader& file, const ValidationOptions& options);

}  // namespace kdpm
