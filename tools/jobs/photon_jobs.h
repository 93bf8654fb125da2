#pragma once
// The photon steps of the pipeline as one call each, from input file to output file:
// kdpm-shoot-photons' and kdpm-build-photons' work, shared with the Python module so both
// refuse the same inputs, record the same metadata and write through the same output discipline.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>

#include "builders/photons/photon_shards.h"
#include "formats/photon_layout.h"
#include "runtime/backend/backend_kind.h"
#include "tools/photons/irradiance_step.h"

namespace kdpm {

struct ShootJob {
    std::uint64_t photons = 0;   // paths to emit; 0: the scene card's, else 262,144
    int bounces = -1;            // most bounces; < 0: the scene card's, else 4
    std::uint32_t seed = 0;
    std::string paths;           // "BEGIN:END" shard of the paths; empty: all
    BackendKind backend = BackendKind::cpu;
};

struct ShootJobResult {
    std::uint64_t emitted = 0;
    std::uint32_t bounces = 0;
    PathRange range;
    PhotonHitsInfo info{};
    std::uint32_t direct_hits = 0;  // stored hits of bounce 0
    std::uint64_t rays = 0;
    double seconds = 0.0;           // the shot alone (no file open, no write)
};

// geometry (.kdg) -> output (.kdph). Throws FormatError / std::invalid_argument with one line.
ShootJobResult shoot_photons_job(const std::filesystem::path& geometry, const std::filesystem::path& output,
                                 const ShootJob& job, const std::function<void(double)>& progress = {});

struct PhotonMapJob {
    bool balanced = false;         // the classic median-split tree instead of VVH
    std::uint32_t leaf_size = 0;   // 0: the builder's default
    double radius = 0.0;           // VVH expected query radius; 0: estimated for k = 32
    std::uint32_t irradiance_every = kDefaultIrradianceEvery;  // 0: no precomputed irradiance
    std::uint32_t irradiance_k = kDefaultIrradianceK;
};

struct PhotonMapJobResult {
    PhotonTreeInfo global{}, caustic{};
    std::uint32_t irradiance_photons = 0;
    double seconds = 0.0;
};

// hits (.kdph, not a shard) -> output (.kdp). Throws FormatError / std::invalid_argument.
PhotonMapJobResult build_photon_map_job(const std::filesystem::path& hits, const std::filesystem::path& output,
                                        const PhotonMapJob& job);

}  // namespace kdpm
