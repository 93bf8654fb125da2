#pragma once
// Exact copies of a triangle (the same three vertices, bit for bit, whatever their material,
// source index or flags) add nothing to what a ray can hit, but no split can separate them: a
// mesh with a million copies of one triangle would make one leaf that every ray through it
// tests a million times. The tree holds the first copy only; it is also the one brute force
// finds first, so hits stay identical. The builder and the validator's coverage check share
// this definition.
#include <cstdint>
#include <span>
#include <vector>

#include "formats/geometry_layout.h"

namespace kdpm {

// For each triangle, whether it is a usable triangle (triangle_is_usable) whose v0, e1 and e2
// equal those of an earlier usable triangle.
std::vector<bool> repeated_triangles(std::span<const TriangleRecord> triangles);

}  // namespace kdpm
