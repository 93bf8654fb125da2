#pragma once
// Where an image's error against a reference lies: the log-ratio error picture and the split of
// relMSE and bias between pixels near geometric edges (creases, silhouettes, thin parts, where
// photon estimates and cache records reach across surfaces) and flat ones.
#include <cstdint>
#include <vector>

#include "runtime/render/image/image.h"

namespace kdpm::bench {

// One byte per pixel, 1 where the first hit's surface changes within `reach` pixels: a
// neighbour's normal turns by more than 30 degrees, its depth differs by more than 5 %, or one of
// the two rays misses. From the normal and depth AOVs of a centre-ray render.
std::vector<std::uint8_t> edge_mask(const AovImages& aovs, int width, int height, int reach = 2);

struct RegionError {
    double relmse = 0;      // over the region's pixels and channels
    double mean_ratio = 0;  // the region's mean / the reference's there (0: no light there)
    double share = 0;       // of the image's pixels
    double error_share = 0; // of the image's summed relative squared error
};

struct RegionSplit {
    RegionError edges, flat;
};

RegionSplit split_error(const Image& test, const Image& reference, const std::vector<std::uint8_t>& edges);

// The error picture: per pixel log2 of the test's luminance over the reference's, red where too
// bright, blue where too dark, full at +-1 stop and black where they agree; luminances below
// 1 % of the reference's mean count as that floor (dark noise is not an error in stops).
Image log_ratio_image(const Image& test, const Image& reference);

// test | reference | error side by side, tone-mapped alike (sRGB in [0, 1]), 3 w x h.
Image side_by_side(const Image& test, const Image& reference);

}  // namespace kdpm::bench
