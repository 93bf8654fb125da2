#pragma once
// Writing and reading photon hit files (.kdph): the shooter's output and the tree builder's input.
#include <filesystem>
#include <span>
#include <vector>

#include "formats/container_writer.h"
#include "formats/metadata.h"
#include "formats/photon_layout.h"

namespace kdpm {

struct PhotonHitSet {
    PhotonHitsInfo info{};
    std::vector<PhotonHit> hits;
};

// Fills stored_count, caustic_count and bounds from the hits; keeps the other fields.
void update_hits_info(PhotonHitSet& set);

// A complete container (info, hits, metadata); write() it, or bytes() for tests.
ContainerWriter photon_hits_writer(const PhotonHitSet& set, const Metadata& metadata);

// Opens, validates (container + photon hit invariants) and copies a .kdph. Throws FormatError.
PhotonHitSet read_photon_hits(const std::filesystem::path& path);

}  // namespace kdpm
