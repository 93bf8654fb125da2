#pragma once
// Adds one photon map's sections (info, nodes, x, y, z, power, directions, flags) to a .kdp.
#include "builders/photons/photon_tree_builder.h"
#include "formats/container_writer.h"

namespace kdpm {

void add_photon_tree_sections(ContainerWriter& writer, PhotonMapKind map, const BuiltPhotonTree& tree);

}  // namespace kdpm
