#pragma once
// Issue 53's instancing rows: the scene's .kdg placed as the object of scenes of instances (one
// instance as it is, one moved, a grid of many), timed against the object's own file in the same
// run: camera packets (the renderer's primary rays), the scene build, the load, the bytes.
#include <cstdint>
#include <filesystem>
#include <string>

#include "tools/bench/median_time.h"

namespace kdpm::bench {

struct InstanceBenchConfig {
    std::string name;
    std::filesystem::path object;    // the scene's built .kdg
    std::filesystem::path work_dir;  // where the cards and scene files go
    std::uint32_t grid_x = 100, grid_z = 100;
    std::uint32_t width = 512, height = 512;
    int pairs = 15;                  // passes timed in pairs per row
    double object_build_ms = 0;      // the object's geometry build, all threads (its scene bench's)
};

struct InstanceFigures {
    bool measured = false;
    std::uint64_t instances = 0, placed_triangles = 0;
    double scene_build_ms = 0;       // card -> grid scene file (kdpm-build-geometry's work)
    double object_build_ms = 0;
    std::uint64_t object_bytes = 0, scene_bytes = 0;
    double load_ms = 0;              // the grid opened: object, placements, BVH, lights
    double runtime_bytes_per_instance = 0;  // placement + BVH nodes + placed lights, in memory
    // Primary rays (camera packets, all threads) / the same camera in the object's own file.
    PairedTimes one_as_is;           // one instance at the identity (walks the object's own tree)
    PairedTimes one_moved;           // one instance moved, its camera moved alike
    PairedTimes grid_inside;         // the grid, the camera moved into its middle instance
    PairedTimes grid_overview;       // the grid seen whole (the camera framed on it) / the object
    double moved_same_hits = 0;      // fraction of moved-instance rays hitting the same triangle
};

InstanceFigures run_instance_bench(const InstanceBenchConfig& config);

std::string format_instance_figures(const std::string& scene, const InstanceFigures& f, bool markdown);

}  // namespace kdpm::bench
