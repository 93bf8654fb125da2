#pragma once
// The CPU backend's trace pass: each work item traces a 4x4 block's camera rays as one packet
// (CameraPacketPass::trace_block) and goes on at once with each pixel's TracePass from its hit,
// while the block's rays and hits are still in registers and cache. The same frame as TracePass
// alone: the packet's rays and hits are the camera's and the single-ray walk's bit for bit.
#include <cstdint>

#include "runtime/render/passes/camera_packet_pass.h"
#include "runtime/render/passes/trace_pass.h"

namespace kdpm {

struct PacketTracePass {
    TracePass trace;

    static std::uint64_t work_items(std::uint32_t width, std::uint32_t height) {
        return CameraPacketPass::work_items(width, height);
    }

    void operator()(std::uint64_t item) const {
        const CameraPacketPass packets{trace.geometry, trace.camera, trace.sample, nullptr};
        RayPacket packet;
        std::uint64_t pixel[kPacketRays];
        Hit hits[kPacketRays];
        packets.trace_block(item, packet, pixel, hits);
        for (std::uint32_t i = 0; i < packet.count; ++i) {
            const Ray r = packet.ray(i);
            trace.trace_pixel(pixel[i], CameraRay{r.origin, r.direction}, &hits[i]);
        }
    }
};

}  // namespace kdpm
