#pragma once
// Mip chains of linear RGB textures: each level box-filters the previous one down to half its
// size (rounded down, at least 1), every texel of the finer level weighted by the area it
// shares with the coarser texel, down to 1 x 1.
#include <cstdint>
#include <vector>

#include "formats/geometry_layout.h"

namespace kdpm {

// The next, coarser level of a width x height image (rows in order).
std::vector<Texel> downsample_box(const std::vector<Texel>& level, std::uint32_t width, std::uint32_t height);

// Level 0 followed by every coarser level, laid out as geometry.texels stores a texture.
std::vector<Texel> build_mip_chain(std::vector<Texel> level0, std::uint32_t width, std::uint32_t height);

}  // namespace kdpm
