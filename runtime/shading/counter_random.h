#pragma once
// Counter-based random numbers: each value is a pure function of its counters, so results never
// depend on the thread count, the order of work or the backend. Two streams, each keyed the way
// its caller counts (changing either changes every image or photon file made so far):
//   counter_random(seed, path, bounce, dimension): photon paths, a 64-bit path index;
//   random01(a, b, c): camera and shading samples, 32-bit (pixel, sample, dimension) counters.
#include <cstdint>

#include "formats/host_device.h"

namespace kdpm {

// A 64-bit finaliser (splitmix64 / Stafford variant 13): every input bit affects every output bit.
KDPM_HD KDPM_INLINE std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// A 32-bit integer hash with good avalanche (the "lowbias32" constants of Chris Wellons).
KDPM_HD KDPM_INLINE std::uint32_t hash_u32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// Uniform in [0, 1) (24 bits) for dimension `dimension` of bounce `bounce` of photon path `path`.
KDPM_HD KDPM_INLINE float counter_random(std::uint32_t seed, std::uint64_t path, std::uint32_t bounce,
                                         std::uint32_t dimension) {
    std::uint64_t h = mix64(path + 0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(seed) + 1));
    h = mix64(h ^ ((static_cast<std::uint64_t>(bounce) << 32) | dimension));
    return static_cast<float>(h >> 40) * (1.0f / 16777216.0f);
}

// Uniform in [0, 1) (24 bits) from three 32-bit counters.
KDPM_HD KDPM_INLINE float random01(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t h = hash_u32(a ^ hash_u32(b + 0x9e3779b9U * hash_u32(c + 0x632be5abU)));
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

// The seeds that keep each render mode's camera-side numbers apart from the others and from the
// photon paths (changing one changes every image of its mode).
namespace random_seed {
inline constexpr std::uint32_t path = 0x70617468u;    // --mode path
inline constexpr std::uint32_t sppm = 0x7370706du;    // --mode sppm
inline constexpr std::uint32_t gather = 0x67617468u;  // final-gather rays and irradiance-cache records
inline constexpr std::uint32_t gather_path = 0x67706174u;  // final gather's path-traced lookup (gather_lookup.h)
}  // namespace random_seed

// One stream of counter_random, handed to samplers that read it by dimension: a mode's seed, a
// 64-bit path index and a counter within the path (a vertex, a ray).
struct RandomStream {
    std::uint32_t seed;
    std::uint64_t path;
    std::uint32_t counter;
    KDPM_HD float operator()(std::uint32_t dimension) const { return counter_random(seed, path, counter, dimension); }
};

}  // namespace kdpm
