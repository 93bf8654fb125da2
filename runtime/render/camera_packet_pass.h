#pragma once
// The CPU backend's first step of a frame sample: the closest hit of every camera ray, traced
// as 16-ray packets of 4x4 pixels (kd_packet_traversal.h), a third to a half of the time of one
// ray at a time on the shipped and shared scenes. The trace pass then starts each pixel from its stored
// hit; the hits are the single-ray walk's bit for bit, so the image is the same.
#include <cstdint>
#include <limits>

#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/kd_packet_traversal.h"
#include "runtime/render/camera.h"

namespace kdpm {

struct CameraPacketPass {
    static constexpr std::uint32_t kBlock = 4;  // kBlock x kBlock pixels = kPacketRays rays
    static_assert(kBlock * kBlock == kPacketRays);

    GeometryView geometry;
    PinholeCamera camera;
    std::uint32_t sample = 0;
    Hit* hits = nullptr;  // per pixel, row-major

    static std::uint64_t work_items(std::uint32_t width, std::uint32_t height) {
        return static_cast<std::uint64_t>((width + kBlock - 1) / kBlock) * ((height + kBlock - 1) / kBlock);
    }

    void operator()(std::uint64_t item) const {
        const std::uint32_t blocks_x = (camera.width + kBlock - 1) / kBlock;
        const std::uint32_t x0 = static_cast<std::uint32_t>(item % blocks_x) * kBlock;
        const std::uint32_t y0 = static_cast<std::uint32_t>(item / blocks_x) * kBlock;
        RayPacket packet;
        std::uint64_t pixel[kPacketRays];
        for (std::uint32_t y = y0; y < y0 + kBlock && y < camera.height; ++y)
            for (std::uint32_t x = x0; x < x0 + kBlock && x < camera.width; ++x) {
                const CameraRay r = camera.ray(x, y, sample);
                pixel[packet.count] = static_cast<std::uint64_t>(y) * camera.width + x;
                // The trace pass's camera ray, exactly.
                packet.set(packet.count++, Ray{r.origin, 0.0f, r.direction, std::numeric_limits<float>::infinity()});
            }
        Hit out[kPacketRays];
        closest_hits(geometry, packet, out);
        for (std::uint32_t i = 0; i < packet.count; ++i) hits[pixel[i]] = out[i];
    }
};

}  // namespace kdpm
