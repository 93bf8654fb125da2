#pragma once
// Counter-based random numbers: a uniform float that is a pure function of (seed, photon path,
// bounce, dimension), so photon paths do not depend on the thread count, the order of work or
// the backend.
#include <cstdint>

#include "formats/host_device.h"

namespace kdpm {

// A 64-bit finaliser (splitmix64 / Stafford variant 13): every input bit affects every output bit.
KDPM_HD KDPM_INLINE std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// Uniform in [0, 1): the top 24 bits of the hash.
KDPM_HD KDPM_INLINE float counter_random(std::uint32_t seed, std::uint64_t path, std::uint32_t bounce,
                                         std::uint32_t dimension) {
    std::uint64_t h = mix64(path + 0x9e3779b97f4a7c15ull * (static_cast<std::uint64_t>(seed) + 1));
    h = mix64(h ^ ((static_cast<std::uint64_t>(bounce) << 32) | dimension));
    return static_cast<float>(h >> 40) * (1.0f / 16777216.0f);
}

}  // namespace kdpm
