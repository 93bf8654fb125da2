#pragma once
// kdpm-bench-quality's converged --mode path references, kept between runs: a reference takes
// far longer than everything else the bench does. Each is a PFM file in the work folder whose
// name carries a hash of everything the image depends on (the .kdg's bytes, size, samples,
// bounce limits, kdpm's version), so a changed input never reuses a stale image: it names
// another file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "runtime/render/image/image.h"

namespace kdpm::bench {

struct ReferenceKey {
    std::string scene;
    std::filesystem::path geometry;  // the .kdg the reference is rendered from (hashed by content)
    std::uint32_t width = 0, height = 0, spp = 0;
    std::uint32_t max_bounces = 0;   // 0: unlimited
    std::uint32_t max_depth = 0;     // mirror/glass bounces
};

// "SCENE-WxH-Nspp-bB-HASH.pfm"
std::string reference_file_name(const ReferenceKey& key);

// The cached image, or nothing when the file is absent. A file that is not a PFM of the key's
// size (this tool publishes only whole files) throws std::runtime_error (one line) and is left alone.
std::optional<Image> load_reference(const std::filesystem::path& file, const ReferenceKey& key);

// Written through kdpm's output discipline (a private temporary, fsync, rename).
void store_reference(const std::filesystem::path& file, const Image& linear);

}  // namespace kdpm::bench
