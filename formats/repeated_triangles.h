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

// What repeated_triangles files a triangle under: a 63-bit hash of its vertices, or
// kUnusableTriangleKey for a triangle that is not usable (triangle_is_usable). Independent per
// triangle, so a caller with threads can compute the keys in parallel.
inline constexpr std::uint64_t kUnusableTriangleKey = ~std::uint64_t{0};
std::uint64_t triangle_key(const TriangleRecord& t);

// For each triangle, whether it is a usable triangle whose v0, e1 and e2 equal those of an
// earlier usable triangle. keys[i] must be triangle_key(triangles[i]).
std::vector<bool> repeated_triangles(std::span<const TriangleRecord> triangles, std::span<const std::uint64_t> keys);
// The same, computing the keys itself.
std::vector<bool> repeated_triangles(std::span<const TriangleRecord> triangles);

}  // namespace kdpm
