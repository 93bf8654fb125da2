#pragma once
// Frame buffers on the host: linear radiance (RGB floats) and the optional AOVs.
#include <cstdint>
#include <vector>

namespace kdpm {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // width * height * 3, row 0 at the top

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0.0f) {}
    std::size_t pixel_count() const { return static_cast<std::size_t>(width) * height; }
    // This image as a w x h one for a writer of every pixel: the storage is kept when large
    // enough (a recycled frame's, Renderer::recycle), and what it held is not cleared.
    void reshape(int w, int h) {
        width = w;
        height = h;
        rgb.resize(pixel_count() * 3);
    }
};

// Arbitrary output variables of the first surface each pixel's centre ray hits.
struct AovSet {
    bool depth = false, normal = false, position = false, triangle = false;
    bool any() const { return depth || normal || position || triangle; }
    bool operator==(const AovSet&) const = default;
};

struct AovImages {
    std::vector<float> depth;          // distance along the ray; +inf for a miss
    std::vector<float> normal;         // 3 per pixel, geometric normal facing the camera; 0 on a miss
    std::vector<float> position;       // 3 per pixel; 0 on a miss
    std::vector<std::int32_t> triangle;  // TriangleRecord::source_index, -1 for a miss
};

}  // namespace kdpm
