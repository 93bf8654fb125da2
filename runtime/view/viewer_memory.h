#pragma once
// Memory the viewer needs for a width x height window, estimated before the window opens: what a
// frame of the renderer needs, plus what the viewer keeps beside it.
#include <cstdint>

namespace kdpm {

// Bytes for the largest frame the viewer can be switched to (photon gathering and the density
// view when the scene has photons), plus the shown frame it keeps while the next one renders,
// the density per pixel, the composed and scaled display images, their 8-bit copy and the
// framebuffer read back for screenshots.
std::uint64_t viewer_memory_bytes(std::uint32_t width, std::uint32_t height, bool have_photons);

}  // namespace kdpm
