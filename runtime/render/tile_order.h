#pragma once
// Work item -> pixel in 8x8 tiles (bands of 8 rows, tiles left to right, rows within a tile):
// neighbouring work items trace neighbouring rays and gather around neighbouring points, which
// keeps the kd-tree and photon nodes in cache on the CPU and keeps GPU warps coherent.
// A bijection on [0, width * height) for any size (edge tiles are narrower or shorter).
#include <cstdint>

#include "formats/host_device.h"

namespace kdpm {

inline constexpr std::uint32_t kTileSize = 8;

KDPM_HD KDPM_INLINE std::uint64_t tiled_pixel(std::uint64_t item, std::uint32_t width, std::uint32_t height) {
    const std::uint64_t band_pixels = static_cast<std::uint64_t>(kTileSize) * width;
    const std::uint32_t band = static_cast<std::uint32_t>(item / band_pixels);
    const std::uint32_t band_top = band * kTileSize;
    const std::uint32_t band_height = height - band_top < kTileSize ? height - band_top : kTileSize;
    const std::uint64_t in_band = item - band * band_pixels;
    const std::uint64_t full_tile_pixels = static_cast<std::uint64_t>(kTileSize) * band_height;
    std::uint32_t tile = static_cast<std::uint32_t>(in_band / full_tile_pixels);
    const std::uint32_t last_tile = (width - 1) / kTileSize;
    if (tile > last_tile) tile = last_tile;
    const std::uint32_t left = tile * kTileSize;
    const std::uint32_t tile_width = width - left < kTileSize ? width - left : kTileSize;
    const std::uint32_t local = static_cast<std::uint32_t>(in_band - tile * full_tile_pixels);
    const std::uint32_t x = left + local % tile_width;
    const std::uint32_t y = band_top + local / tile_width;
    return static_cast<std::uint64_t>(y) * width + x;
}

}  // namespace kdpm
