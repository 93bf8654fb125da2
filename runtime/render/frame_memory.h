#pragma once
// Memory a frame needs, estimated before any buffer is allocated, so that an image too large
// for the machine is a clear error instead of a process the OOM killer ends.
#include <cstdint>

#include "runtime/render/image/image.h"

namespace kdpm {

// Bytes for a width x height frame: the passes' buffers (frame_loop.h), the result images
// (linear, exposed, display), the AOVs asked for, and the copies image output makes.
std::uint64_t frame_memory_bytes(std::uint32_t width, std::uint32_t height, bool gather_photons, const AovSet& aovs);

// Memory this process can still get: MemAvailable, or less under an address-space limit.
std::uint64_t available_memory_bytes();

// Throws std::runtime_error ("a WxH frame needs about X GiB of memory, but only Y GiB is
// available") when `needed` exceeds `available`.
void check_frame_memory(std::uint32_t width, std::uint32_t height, std::uint64_t needed, std::uint64_t available);

}  // namespace kdpm
