#pragma once
// Synthetic photon sets for the photon tests: photons on a few walls of a box (as a shooter
// leaves them, including coincident points), plus a uniform cloud; deterministic per seed.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "builders/photons/photon_hits_file.h"

namespace kdpm::test {

PhotonHitSet synthetic_photons(std::uint32_t count, std::uint32_t seed);

// Writes the set as a .kdph through the project's writer.
void write_photon_hits_file(const PhotonHitSet& set, const std::filesystem::path& path);

}  // namespace kdpm::test
