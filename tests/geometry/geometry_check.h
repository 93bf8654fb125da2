#pragma once
// Builds a .kdg in memory from triangles, validates it exhaustively and compares closest hits
// through the tree with brute force; shared by several geometry tests.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "builders/geometry/geometry_file_builder.h"
#include "formats/container_reader.h"
#include "formats/tree_validation.h"
#include "runtime/geometry/geometry_file.h"
#include "runtime/geometry/scene_traversal.h"

namespace kdpm::test {

// Rays whose tree result disagrees with brute force, over one walk: not found on one side,
// another distance (relative 1e-5), or another triangle not at the same distance (an exact tie
// is allowed).
inline int count_walk_mismatches(const GeometryView& g, const std::vector<Ray>& rays) {
    int bad = 0;
    for (const Ray& r : rays) {
        const Hit a = closest_hit(g, r), b = closest_hit_brute_force(g, r);
        if (a.found() != b.found()) {
            ++bad;
            continue;
        }
        if (!a.found()) {
            if (occluded(g, r)) ++bad;
            continue;
        }
        if (std::fabs(a.t - b.t) > 1e-5f * std::fabs(b.t)) ++bad;
        else if (a.triangle != b.triangle && a.t != b.t) ++bad;
        if (!occluded(g, r)) ++bad;
    }
    return bad;
}

// count_walk_mismatches for closest_hit and occluded as the runtime calls them (the wide walk
// where the file has the wide tree, format 1.2) and, for such a file, for the binary walk too.
inline int count_mismatches(const GeometryView& g, const std::vector<Ray>& rays) {
    int bad = count_walk_mismatches(g, rays);
    if (g.wide != nullptr) {
        GeometryView binary = g;
        binary.wide = nullptr;
        binary.wide_node_count = 0;
        bad += count_walk_mismatches(binary, rays);
    }
    return bad;
}

// Build parameters of one quality. A fast build bins nodes down to a small size here, so that
// test-sized inputs exercise the binned splits and not only the exact sweep below them.
inline KdBuildParams quality_params(KdBuildQuality quality) {
    KdBuildParams p;
    p.quality = quality;
    p.exact_below = 32;
    return p;
}

inline std::vector<std::uint8_t> build_bytes(const Scene& scene, const KdBuildParams& params = {}) {
    return build_geometry_file(scene, params).writer.bytes();
}

// Build, validate exhaustively, reopen through GeometryFile and compare rays with brute force.
inline void check_triangles(std::vector<TriangleRecord> tris, const std::vector<Ray>& rays,
                            const KdBuildParams& params = {}) {
    const auto bytes = build_bytes(scene_from_triangles(std::move(tris)), params);
    const auto reader = ContainerReader::from_bytes(bytes, "test.kdg");
    ValidationOptions exhaustive;
    exhaustive.exhaustive = true;
    REQUIRE_NOTHROW(validate_file(reader, exhaustive));
    const GeometryFile file = GeometryFile::from_bytes(bytes, "test.kdg");
    CHECK(count_mismatches(file.view(), rays) == 0);
}

}  // namespace kdpm::test
