#pragma once
// Scene -> SAH kd-tree -> the sections of a .kdg file. Used by kdpm-build-geometry and by any
// test that needs a geometry file built in-process from its own triangles.
#include <functional>

#include "builders/geometry/sah/kd_build_params.h"
#include "builders/geometry/sah/kd_tree.h"
#include "builders/geometry/scene.h"
#include "formats/container_writer.h"

namespace kdpm {

struct GeometryBuild {
    ContainerWriter writer;  // the complete file: writer.write(path) or writer.bytes()
    KdTreeStats stats;
    std::uint64_t repeated_triangles = 0;  // exact copies left out of the tree (repeated_triangles.h)
};

// Builds the tree over scene.triangles and assembles every section; the scene needs a camera
// (set has_camera or call frame_camera; one is framed automatically otherwise).
GeometryBuild build_geometry_file(const Scene& scene, const KdBuildParams& params,
                                  const std::function<void(double)>& progress = {});

// The sections of a .kdg file for `scene` with an already built `tree` (tests use it to write
// deliberately broken trees).
ContainerWriter assemble_geometry_file(const Scene& scene, const KdTree& tree, const KdBuildParams& params);

// A scene from bare triangles (one white diffuse material, no lights, framed camera): tests.
Scene scene_from_triangles(std::vector<TriangleRecord> triangles);

}  // namespace kdpm
