#pragma once
// The size of a rendered image: the requested sides, else the camera's; one side alone keeps the
// camera's aspect ratio. kdpm-render and kdpm-view both size their frames by this rule.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "formats/camera_check.h"
#include "formats/geometry_layout.h"

namespace kdpm {

struct ImageSize {
    std::uint32_t width = 0, height = 0;
};

// width, height: 0 for "the camera's". Throws a one-line error outside 1..kMaxImageSide.
inline ImageSize image_size(std::uint32_t width, std::uint32_t height, const CameraRecord& camera) {
    ImageSize size{width ? width : camera.width, height ? height : camera.height};
    if (width && !height && camera.width && camera.height)
        size.height = std::max<std::uint32_t>(
            1, static_cast<std::uint32_t>(std::lround(static_cast<double>(width) * camera.height / camera.width)));
    if (height && !width && camera.width && camera.height)
        size.width = std::max<std::uint32_t>(
            1, static_cast<std::uint32_t>(std::lround(static_cast<double>(height) * camera.width / camera.height)));
    if (size.width == 0 || size.height == 0 || size.width > kMaxImageSide || size.height > kMaxImageSide)
        throw std::runtime_error("image size " + std::to_string(size.width) + "x" + std::to_string(size.height) +
                                 " is out of range (1.." + std::to_string(kMaxImageSide) + ")");
    return size;
}

}  // namespace kdpm
