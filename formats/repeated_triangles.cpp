#include "formats/repeated_triangles.h"

#include <bit>
#include <cstring>

#include "formats/checksum.h"
#include "formats/triangle_clip.h"

namespace kdpm {

namespace {

bool same_vertices(const TriangleRecord& a, const TriangleRecord& b) {
    return std::memcmp(a.v0, b.v0, sizeof a.v0) == 0 && std::memcmp(a.e1, b.e1, sizeof a.e1) == 0 &&
           std::memcmp(a.e2, b.e2, sizeof a.e2) == 0;
}

std::uint64_t vertex_hash(const TriangleRecord& t) {
    float key[9];
    std::memcpy(key, t.v0, sizeof t.v0);
    std::memcpy(key + 3, t.e1, sizeof t.e1);
    std::memcpy(key + 6, t.e2, sizeof t.e2);
    return checksum64(key, sizeof key);
}

}  // namespace

std::vector<bool> repeated_triangles(std::span<const TriangleRecord> triangles) {
    const std::size_t n = triangles.size();
    std::vector<bool> repeated(n, false);
    // Open addressing, at most half full: slot holds index + 1 of the first triangle with a key.
    const std::size_t capacity = std::bit_ceil(2 * n + 2);
    std::vector<std::uint32_t> slots(capacity, 0);
    // The keys first, so that the insertions can ask for their slot's cache line well before
    // they read it: the table outgrows a core's own cache and its lines are read in random order.
    constexpr std::uint64_t kUnusable = ~std::uint64_t{0};
    std::vector<std::uint64_t> home(n);
    for (std::size_t i = 0; i < n; ++i)
        home[i] = triangle_is_usable(triangles[i]) ? vertex_hash(triangles[i]) & (capacity - 1) : kUnusable;
    constexpr std::size_t kAhead = 16;
    for (std::size_t i = 0; i < n; ++i) {
        if (i + kAhead < n && home[i + kAhead] != kUnusable) __builtin_prefetch(&slots[home[i + kAhead]]);
        if (home[i] == kUnusable) continue;
        const TriangleRecord& t = triangles[i];
        for (std::size_t s = home[i];; s = (s + 1) & (capacity - 1)) {
            if (slots[s] == 0) {
                slots[s] = static_cast<std::uint32_t>(i + 1);
                break;
            }
            if (same_vertices(triangles[slots[s] - 1], t)) {
                repeated[i] = true;
                break;
            }
        }
    }
    return repeated;
}

}  // namespace kdpm
