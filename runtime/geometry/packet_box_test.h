#pragma once
// Which rays of a 16-ray packet enter an axis-aligned box within their own (tmin, tmax): the
// instance BVH's node test for a packet, four lanes per SSE2 instruction where the CPU has SSE2
// (every x86-64), lane by lane elsewhere. Both answer as instance_detail::enter_box does, the
// exit raised by kExitSlack; an axis whose slab distance is NaN (a zero direction component
// with the origin on the slab's plane) never refuses a lane.
#include <cstdint>

#include "runtime/geometry/box_exit_slack.h"

#if defined(__SSE2__) && !defined(__CUDACC__)
#include <emmintrin.h>
#endif

namespace kdpm {

struct PacketBoxTest {
    static constexpr std::uint32_t kLanes = 16;
    alignas(16) float origin[3][kLanes];
    alignas(16) float inv[3][kLanes];  // 1 / direction
    alignas(16) float tmin[kLanes];
    alignas(16) float tmax[kLanes];    // lowered as each lane finds closer hits

    // Lanes past count copy lane 0 (their answers are the caller's to ignore).
    PacketBoxTest(const float (&o)[3][kLanes], const float (&d)[3][kLanes], const float* t0, const float* t1,
                  std::uint32_t count) {
        for (std::uint32_t i = 0; i < kLanes; ++i) {
            const std::uint32_t s = i < count ? i : 0;
            for (int a = 0; a < 3; ++a) origin[a][i] = o[a][s], inv[a][i] = d[a][s];
            tmin[i] = t0[s];
            tmax[i] = t1[s];
        }
#if defined(__SSE2__) && !defined(__CUDACC__)
        for (int a = 0; a < 3; ++a)
            for (std::uint32_t g = 0; g < kLanes; g += 4)
                _mm_store_ps(inv[a] + g, _mm_div_ps(_mm_set1_ps(1.0f), _mm_load_ps(inv[a] + g)));
#else
        for (int a = 0; a < 3; ++a)
            for (std::uint32_t i = 0; i < kLanes; ++i) inv[a][i] = 1.0f / inv[a][i];
#endif
    }

    // Bit i: lane i enters [lo, hi].
    std::uint32_t entering(const float (&lo)[3], const float (&hi)[3]) const {
        std::uint32_t lanes = 0;
#if defined(__SSE2__) && !defined(__CUDACC__)
        const __m128 slack = _mm_set1_ps(kExitSlack), zero = _mm_setzero_ps();
        for (std::uint32_t g = 0; g < kLanes; g += 4) {
            __m128 t0 = _mm_load_ps(tmin + g), t1 = _mm_load_ps(tmax + g);
            for (int a = 0; a < 3; ++a) {
                const __m128 o = _mm_load_ps(origin[a] + g), r = _mm_load_ps(inv[a] + g);
                const __m128 tl = _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(lo[a]), o), r);
                const __m128 th = _mm_mul_ps(_mm_sub_ps(_mm_set1_ps(hi[a]), o), r);
                // The near plane by the direction's sign (so a NaN stays on its own side), then
                // max/min with the NaN first: SSE2 returns the second operand then.
                const __m128 forward = _mm_cmpge_ps(r, zero);
                const __m128 tn = _mm_or_ps(_mm_and_ps(forward, tl), _mm_andnot_ps(forward, th));
                const __m128 tf = _mm_or_ps(_mm_and_ps(forward, th), _mm_andnot_ps(forward, tl));
                t0 = _mm_max_ps(tn, t0);
                t1 = _mm_min_ps(_mm_mul_ps(tf, slack), t1);
            }
            lanes |= static_cast<std::uint32_t>(_mm_movemask_ps(_mm_cmple_ps(t0, t1))) << g;
        }
#else
        for (std::uint32_t i = 0; i < kLanes; ++i) {
            float t0 = tmin[i], t1 = tmax[i];
            for (int a = 0; a < 3; ++a) {
                const float tl = (lo[a] - origin[a][i]) * inv[a][i], th = (hi[a] - origin[a][i]) * inv[a][i];
                const bool forward = inv[a][i] >= 0.0f;
                const float tn = forward ? tl : th, tf = (forward ? th : tl) * kExitSlack;
                if (tn > t0) t0 = tn;
                if (tf < t1) t1 = tf;
            }
            lanes |= static_cast<std::uint32_t>(t0 <= t1) << i;
        }
#endif
        return lanes;
    }
};

}  // namespace kdpm
