#pragma once
// The closest hit of every camera ray of a frame sample, traced as 16-ray packets of 4x4 pixels
// (kd_packet_traversal.h), since a packet reads each node once and tests several rays per
// instruction; the hits are the single-ray walk's bit for bit. The CPU backend's trace pass
// starts each pixel from its packet's hit (PacketTracePass); this pass stores them per pixel.
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
        RayPacket packet;
        std::uint64_t pixel[kPacketRays];
        Hit out[kPacketRays];
        trace_block(item, packet, pixel, out);
        for (std::uint32_t i = 0; i < packet.count; ++i) hits[pixel[i]] = out[i];
    }

    // Block `item`'s camera rays (lane i: the ray of pixel[i], row-major index) and their
    // closest hits.
    void trace_block(std::uint64_t item, RayPacket& packet, std::uint64_t (&pixel)[kPacketRays],
                     Hit (&out)[kPacketRays]) const {
        const std::uint32_t blocks_x = (camera.width + kBlock - 1) / kBlock;
        const std::uint32_t x0 = static_cast<std::uint32_t>(item % blocks_x) * kBlock;
        const std::uint32_t y0 = static_cast<std::uint32_t>(item / blocks_x) * kBlock;
        bool made = false;
#if defined(KDPM_PACKET_SIMD)
        if (camera.samples <= 1 && x0 + kBlock <= camera.width && y0 + kBlock <= camera.height) {
            centre_rays(x0, y0, packet);
            for (std::uint32_t i = 0; i < kPacketRays; ++i)
                pixel[i] = static_cast<std::uint64_t>(y0 + i / kBlock) * camera.width + x0 + i % kBlock;
            made = true;
        }
#endif
        if (!made) {  // jittered samples and partial edge blocks: the camera's rays one by one
            for (std::uint32_t y = y0; y < y0 + kBlock && y < camera.height; ++y)
                for (std::uint32_t x = x0; x < x0 + kBlock && x < camera.width; ++x) {
                    const CameraRay r = camera.ray(x, y, sample);
                    pixel[packet.count] = static_cast<std::uint64_t>(y) * camera.width + x;
                    // The trace pass's camera ray, exactly.
                    packet.set(packet.count++, Ray{r.origin, 0.0f, r.direction, std::numeric_limits<float>::infinity()});
                }
        }
        closest_hits(geometry, packet, out);
    }

#if defined(KDPM_PACKET_SIMD)
    // The pixel-centre rays of the full block at (x0, y0), row by row, four lanes per SSE2
    // instruction: PinholeCamera::ray's operations in its order (glm's normalize is v times
    // 1 / sqrt of the dot product, summed x + y then z), so the trace pass's rays bit for bit.
    void centre_rays(std::uint32_t x0, std::uint32_t y0, RayPacket& packet) const {
        static_assert(kBlock == 4);
        const __m128 one = _mm_set1_ps(1.0f), two = _mm_set1_ps(2.0f);
        const __m128 columns = _mm_setr_ps(static_cast<float>(x0), static_cast<float>(x0 + 1),
                                           static_cast<float>(x0 + 2), static_cast<float>(x0 + 3));
        const __m128 width = _mm_set1_ps(static_cast<float>(camera.width));
        const __m128 ndc_x = _mm_sub_ps(_mm_div_ps(_mm_mul_ps(two, _mm_add_ps(columns, _mm_set1_ps(0.5f))), width), one);
        for (std::uint32_t row = 0; row < kBlock; ++row) {
            const float y = static_cast<float>(y0 + row);
            const __m128 ndc_y = _mm_set1_ps(1.0f - 2.0f * (y + 0.5f) / static_cast<float>(camera.height));
            __m128 d[3];
            for (int a = 0; a < 3; ++a)
                d[a] = _mm_add_ps(_mm_add_ps(_mm_set1_ps(camera.forward[a]), _mm_mul_ps(ndc_x, _mm_set1_ps(camera.right[a]))),
                                  _mm_mul_ps(ndc_y, _mm_set1_ps(camera.up[a])));
            const __m128 length2 =
                _mm_add_ps(_mm_add_ps(_mm_mul_ps(d[0], d[0]), _mm_mul_ps(d[1], d[1])), _mm_mul_ps(d[2], d[2]));
            const __m128 inverse = _mm_div_ps(one, _mm_sqrt_ps(length2));
            for (int a = 0; a < 3; ++a) {
                _mm_storeu_ps(&packet.direction[a][row * kBlock], _mm_mul_ps(d[a], inverse));
                _mm_storeu_ps(&packet.origin[a][row * kBlock], _mm_set1_ps(camera.eye[a]));
            }
            _mm_storeu_ps(&packet.tmin[row * kBlock], _mm_setzero_ps());
            _mm_storeu_ps(&packet.tmax[row * kBlock], _mm_set1_ps(std::numeric_limits<float>::infinity()));
        }
        packet.count = kPacketRays;
    }
#endif
};

}  // namespace kdpm
