#include "formats/repeated_triangles.h"

#include <bit>
#include <cassert>
#include <cstring>

#include "formats/checksum.h"
#include "formats/triangle_clip.h"

namespace kdpm {

namespace {

bool same_vertices(const TriangleRecord& a, const TriangleRecord& b) {
    return std::memcmp(a.v0, b.v0, sizeof a.v0) == 0 && std::memcmp(a.e1, b.e1, sizeof a.e1) == 0 &&
           std::memcmp(a.e2, b.e2, sizeof a.e2) == 0;
}

}  // namespace

std::uint64_t triangle_key(const TriangleRecord& t) {
    if (!triangle_is_usable(t)) return kUnusableTriangleKey;
    float key[9];
    std::memcpy(key, t.v0, sizeof t.v0);
    std::memcpy(key + 3, t.e1, sizeof t.e1);
    std::memcpy(key + 6, t.e2, sizeof t.e2);
    return checksum64(key, sizeof key) >> 1;  // never kUnusableTriangleKey
}

std::vector<bool> repeated_triangles(std::span<const TriangleRecord> triangles, std::span<const std::uint64_t> keys) {
    assert(keys.size() == triangles.size());
    const std::size_t n = triangles.size();
    std::vector<bool> repeated(n, false);
    // Open addressing, at most half full. A slot holds index + 1 of the first triangle with a
    // key and the key's upper half: the vertices of an occupied slot's triangle are compared
    // only when that half matches, not for every collision (a read of a record in random order).
    struct Slot {
        std::uint32_t index_plus_one, tag;
    };
    const std::size_t capacity = std::bit_ceil(2 * n + 2);
    std::vector<Slot> slots(capacity, Slot{0, 0});
    // Each insertion asks for its slot's cache line well before it reads it: the table outgrows
    // a core's own cache and its lines are read in random order.
    constexpr std::size_t kAhead = 16;
    for (std::size_t i = 0; i < n; ++i) {
        if (i + kAhead < n && keys[i + kAhead] != kUnusableTriangleKey)
            __builtin_prefetch(&slots[keys[i + kAhead] & (capacity - 1)]);
        const std::uint64_t key = keys[i];
        if (key == kUnusableTriangleKey) continue;
        const std::uint32_t tag = static_cast<std::uint32_t>(key >> 32);
        for (std::size_t s = key & (capacity - 1);; s = (s + 1) & (capacity - 1)) {
            if (slots[s].index_plus_one == 0) {
                slots[s] = Slot{static_cast<std::uint32_t>(i + 1), tag};
                break;
            }
            if (slots[s].tag == tag && same_vertices(triangles[slots[s].index_plus_one - 1], triangles[i])) {
                repeated[i] = true;
                break;
            }
        }
    }
    return repeated;
}

std::vector<bool> repeated_triangles(std::span<const TriangleRecord> triangles) {
    std::vector<std::uint64_t> keys(triangles.size());
    for (std::size_t i = 0; i < triangles.size(); ++i) keys[i] = triangle_key(triangles[i]);
    return repeated_triangles(triangles, keys);
}

}  // namespace kdpm
