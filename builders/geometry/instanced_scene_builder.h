#pragma once
// A card of instances -> a scene .kdg (format 1.3) that places object .kdg files: each object
// opened and validated, its content hash and triangle count recorded, its path stored relative
// to the output's folder; the camera framed on the placed objects when the card has none.
#include <cstdint>
#include <filesystem>

#include "builders/geometry/scene_card.h"
#include "formats/container_writer.h"

namespace kdpm {

struct InstancedSceneBuild {
    ContainerWriter writer{FileKind::geometry};
    std::uint64_t placed_triangles = 0;  // every instance's object's triangles
};

// Throws FormatError with one line (an object missing, invalid, itself a scene of instances, or
// with a path too long to store).
InstancedSceneBuild build_instanced_scene(const InstanceCard& card, const std::filesystem::path& card_path,
                                          const std::filesystem::path& output);

}  // namespace kdpm
