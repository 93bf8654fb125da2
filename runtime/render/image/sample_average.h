#pragma once
// A frame's linear image from its per-pixel sums of samples, on the host's threads because on
// one thread it takes a noticeable share of a frame.
#include <cstdint>

#include <glm/vec3.hpp>

#include "runtime/render/image/image.h"

namespace kdpm {

// out (resized to width x height, its storage reused) holds sums[i] * inv_samples for each pixel i.
void average_samples(const glm::vec3* sums, std::uint32_t width, std::uint32_t height, float inv_samples, Image& out);

}  // namespace kdpm
