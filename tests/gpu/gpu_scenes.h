#pragma once
// Scenes for the gpu tests, built in-process from their scene cards: the geometry kd-tree, and
// on request a photon map shot and built on the CPU, as kdpm-render would load them.
// The cards are found under $KDPM_SOURCE_DIR (the GPU bundle sets it) or the source tree; the
// shared meshes under $KDPM_SCENES or ../shared/scenes.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "runtime/geometry/geometry_file.h"
#include "runtime/photons/photon_map_file.h"
#include "runtime/render/scene_views.h"

namespace kdpm::test {

struct GpuTestScene {
    std::optional<GeometryFile> geometry;
    std::optional<PhotonMapFile> photons;
    SceneViews views;
};

// Throws when the card or its mesh is missing.
GpuTestScene build_gpu_test_scene(const std::string& name, std::uint64_t photons);

// The Cornell box is shipped; the others exist only where the shared scenes do.
bool gpu_test_scene_available(const std::string& name);

}  // namespace kdpm::test
