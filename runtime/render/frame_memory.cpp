#include "runtime/render/frame_memory.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>

#include <glm/vec3.hpp>

#include "runtime/render/frame_buffers.h"

namespace kdpm {

std::uint64_t frame_memory_bytes(std::uint32_t width, std::uint32_t height, bool gather_photons, const AovSet& aovs) {
    const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
    std::uint64_t per_pixel = 2 * sizeof(glm::vec3) + sizeof(std::uint32_t)  // accum, emitted, vertex count
                              + kMaxDiffuseVertices * sizeof(DiffuseVertex);
    if (gather_photons) per_pixel += kMaxDiffuseVertices * sizeof(glm::vec3);
    if (aovs.depth) per_pixel += 2 * sizeof(float);  // the pass's buffer and the result image
    if (aovs.normal) per_pixel += 2 * sizeof(glm::vec3);
    if (aovs.position) per_pixel += 2 * sizeof(glm::vec3);
    if (aovs.triangle) per_pixel += 2 * sizeof(std::int32_t);
    per_pixel += 3 * 3 * sizeof(float);  // linear, exposed and display images
    per_pixel += 2 * 3 * sizeof(float);  // image output: channel planes and their interleaved copy
    return pixels * per_pixel;
}

std::uint64_t available_memory_bytes() {
    std::uint64_t available = 0;
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:") available = kib * 1024;
    if (available == 0) available = static_cast<std::uint64_t>(::sysconf(_SC_AVPHYS_PAGES)) * ::sysconf(_SC_PAGESIZE);
    struct rlimit lim{};
    if (::getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY && lim.rlim_cur < available)
        available = lim.rlim_cur;
    return available;
}

void check_frame_memory(std::uint32_t width, std::uint32_t height, std::uint64_t needed, std::uint64_t available) {
    if (needed <= available) return;
    char text[200];
    std::snprintf(text, sizeof text,
                  "a %ux%u frame needs about %.1f GiB of memory, but only %.1f GiB is available; render a smaller "
                  "image (--width, --height)",
                  width, height, needed / 1073741824.0, available / 1073741824.0);
    throw std::runtime_error(text);
}

}  // namespace kdpm
