#pragma once
// Counter-based random numbers: a value is a pure function of (pixel, sample, dimension), so an
// image never depends on the order in which threads or GPU blocks ran.
#include <cstdint>

#include "formats/host_device.h"

namespace kdpm {

// A 32-bit integer hash with good avalanche (the "lowbias32" constants of Chris Wellons).
KDPM_HD KDPM_INLINE std::uint32_t hash_u32(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// Uniform in [0, 1) from three counters.
KDPM_HD KDPM_INLINE float random01(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t h = hash_u32(a ^ hash_u32(b + 0x9e3779b9U * hash_u32(c + 0x632be5abU)));
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

}  // namespace kdpm
