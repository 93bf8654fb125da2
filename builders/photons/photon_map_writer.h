#pragma once
// Photon hits -> the complete photon kd-tree file (.kdp): the global map over every stored photon
// and the caustic map over the caustic ones, with their build parameters and statistics in the
// metadata. Shared by kdpm-build-photons and kdpm-bench.
#include "builders/photons/irradiance_map_builder.h"
#include "builders/photons/photon_hits_file.h"
#include "builders/photons/photon_tree_builder.h"
#include "formats/container_writer.h"

namespace kdpm {

struct PhotonMapBuild {
    ContainerWriter writer{FileKind::photon_tree};  // write(path), or bytes() for tests
    PhotonTreeInfo global{};
    PhotonTreeInfo caustic{};
    PhotonTreeInfo irradiance{};  // zeroed when no irradiance map was asked for
};

// `metadata` carries the tool and source; the builder, leaf size, radius and statistics are added.
// With `irradiance`, the file also holds the irradiance map over the photons it chooses.
PhotonMapBuild build_photon_map_file(const PhotonHitSet& set, const PhotonTreeOptions& options, Metadata metadata,
                                     const IrradiancePrecompute& irradiance = {});

}  // namespace kdpm
