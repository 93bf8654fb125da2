#include "runtime/render/image/sample_average.h"

#include "runtime/backend/cpu_parallel_for.h"

namespace kdpm {

void average_samples(const glm::vec3* sums, std::uint32_t width, std::uint32_t height, float inv_samples, Image& out) {
    out.reshape(static_cast<int>(width), static_cast<int>(height));
    float* rgb = out.rgb.data();
    cpu_parallel_for(out.pixel_count(), [=](std::uint64_t i) {
        for (int c = 0; c < 3; ++c) rgb[i * 3 + c] = sums[i][c] * inv_samples;
    }, 4096);
}

}  // namespace kdpm
