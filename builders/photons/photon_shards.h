#pragma once
// Photon shooting split by path range. A shard is a .kdph that holds the hits of paths
// [begin, end) of a run of N paths; its metadata says so (parameters "paths" = "BEGIN:END", with
// "photons" = N, "seed", "bounces" and the scene's source_hash). Merging shards that cover 0:N
// exactly gives the file one run over all N paths writes, byte for byte.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "builders/photons/photon_hits_file.h"
#include "formats/metadata.h"

namespace kdpm {

struct PathRange {
    std::uint64_t begin = 0, end = 0;  // [begin, end)
    bool operator==(const PathRange&) const = default;
};

// The metadata parameter that records a .kdph's path range.
inline constexpr const char* kPathsParameter = "paths";

// "BEGIN:END" with BEGIN < END <= total; throws std::invalid_argument naming the problem.
PathRange parse_path_range(std::string_view text, std::uint64_t total);
std::string path_range_text(PathRange range);

// The paths a .kdph holds: its "paths" parameter, or all of 0:emitted_count for files written
// before shards existed. Throws FormatError when the parameter is malformed or disagrees with
// emitted_count.
PathRange photon_hits_path_range(const Metadata& metadata, const PhotonHitsInfo& info);

struct PhotonShard {
    std::string name;  // for messages
    PhotonHitSet set;
    Metadata metadata;
    PathRange paths;
};

// Reads and validates a .kdph with its metadata. Throws FormatError.
PhotonShard read_photon_shard(const std::filesystem::path& path);

struct MergedPhotons {
    PhotonHitSet set;
    Metadata metadata;
};

// Joins shards (in any order) in path order. Throws std::invalid_argument with a one-line reason
// when they come from different shooting runs (scene, seed, photon total, bounces, version) or
// do not cover 0:N exactly once.
MergedPhotons merge_photon_shards(std::vector<PhotonShard> shards);

}  // namespace kdpm
