#pragma once
// SSE2 operations on four float lanes, in the shape moller_trumbore.h and kd_packet_walk.inc are
// written over (V, M, add, sub, ..., movemask): the leaf test of four triangles against a ray and
// the packet walk's narrowest set. CPU only, on every x86-64.
#include <cstdint>

#if defined(__SSE2__) && defined(__x86_64__) && !defined(__CUDA_ARCH__)
#include <emmintrin.h>
#define KDPM_SSE2_OPS 1
#endif

namespace kdpm {

#if defined(KDPM_SSE2_OPS)
struct Sse2Ops {
    using V = __m128;
    using VI = __m128i;
    using M = __m128;  // lane masks: all bits set or clear per lane
    static constexpr int kWidth = 4;
    static V load(const float* p) { return _mm_loadu_ps(p); }
    static void store(float* p, V v) { _mm_storeu_ps(p, v); }
    static void store_i(std::uint32_t* p, VI v) { _mm_storeu_si128(reinterpret_cast<__m128i*>(p), v); }
    static V set1(float x) { return _mm_set1_ps(x); }
    static VI set1_i(int x) { return _mm_set1_epi32(x); }
    static V zero() { return _mm_setzero_ps(); }
    static M not_(M m) { return _mm_andnot_ps(m, _mm_castsi128_ps(_mm_set1_epi32(-1))); }
    static V add(V a, V b) { return _mm_add_ps(a, b); }
    static V sub(V a, V b) { return _mm_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm_mul_ps(a, b); }
    static V div(V a, V b) { return _mm_div_ps(a, b); }
    static V lt(V a, V b) { return _mm_cmplt_ps(a, b); }
    static V le(V a, V b) { return _mm_cmple_ps(a, b); }
    static V gt(V a, V b) { return _mm_cmpgt_ps(a, b); }
    static V ge(V a, V b) { return _mm_cmpge_ps(a, b); }
    static V nle(V a, V b) { return _mm_cmpnle_ps(a, b); }  // !(a <= b): true when unordered
    static V neq(V a, V b) { return _mm_cmpneq_ps(a, b); }  // a != b: true when unordered
    static V eq_i(VI a, VI b) { return _mm_castsi128_ps(_mm_cmpeq_epi32(a, b)); }
    static V and_(V a, V b) { return _mm_and_ps(a, b); }
    static V or_(V a, V b) { return _mm_or_ps(a, b); }
    static V andnot(V a, V b) { return _mm_andnot_ps(a, b); }  // ~a & b
    static int movemask(V v) { return _mm_movemask_ps(v); }
    static V select(V mask, V a, V b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }
    static VI select_i(V mask, VI a, VI b) {
        const VI m = _mm_castps_si128(mask);
        return _mm_or_si128(_mm_and_si128(m, a), _mm_andnot_si128(m, b));
    }
    // The lanes whose bit is set in `bits` (the group's kWidth bits).
    static V lanes_of(std::uint32_t bits) {
        const VI lane_bit = _mm_set_epi32(8, 4, 2, 1);
        return eq_i(_mm_and_si128(_mm_set1_epi32(static_cast<int>(bits)), lane_bit), lane_bit);
    }
};
#endif

}  // namespace kdpm
