#include "runtime/view/viewer_memory.h"

#include "runtime/render/frame_memory.h"

namespace kdpm {

std::uint64_t viewer_memory_bytes(std::uint32_t width, std::uint32_t height, bool have_photons) {
    // Every frame carries depth and normal AOVs (picking, density view); positions in the density view.
    AovSet aovs;
    aovs.depth = aovs.normal = true;
    aovs.position = have_photons;
    const std::uint64_t frame = frame_memory_bytes(width, height, have_photons, aovs);
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
    std::uint64_t per_pixel = 3 * 3 * sizeof(float)                        // the shown frame's linear, exposed, display
                              + sizeof(float) + 3 * sizeof(float) + sizeof(float)  // its depth, normal AOVs...
                              + (have_photons ? 3 * sizeof(float) + sizeof(float) : 0)  // ...position, density
                              + 2 * 3 * sizeof(float)                      // composed and scaled display images
                              + 3 * 3;                                     // 8-bit copy, framebuffer and its flip
    return frame + pixels * per_pixel;
}

}  // namespace kdpm
