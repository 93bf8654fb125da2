#pragma once
// A .kdg file from a scene card, a mesh or a Scene in memory: the whole of kdpm-build-geometry's
// work, shared with the Python module so both check, build and write the same file the same way.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "builders/geometry/sah/kd_build_params.h"
#include "builders/geometry/sah/kd_tree_stats.h"
#include "builders/geometry/scene.h"

namespace kdpm {

struct GeometryJobResult {
    std::size_t triangles = 0;          // in the scene, before repeated copies are left out
    KdTreeStats stats;
    std::vector<std::string> warnings;  // one line each: import, repeated triangles, a huge leaf
    double import_ms = 0.0, build_ms = 0.0;
    std::size_t instances = 0, objects = 0;  // a card of instances: placements, distinct object files
};

// Checks the destination before any work, imports `input`, builds and writes `output` through
// the output discipline. A card of instances makes a scene that places its object files. Throws FormatError / std::invalid_argument with one line.
GeometryJobResult build_geometry_job(const std::filesystem::path& input, const std::filesystem::path& output,
                                     const KdBuildParams& params, const std::function<void(double)>& progress = {});

// The same over a scene already in memory (no input file to check against).
GeometryJobResult build_geometry_job(const Scene& scene, const std::filesystem::path& output,
                                     const KdBuildParams& params, const std::function<void(double)>& progress = {});

}  // namespace kdpm
