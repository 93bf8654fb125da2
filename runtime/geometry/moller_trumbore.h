#pragma once
// Möller–Trumbore ray/triangle intersection over the stored (v0, e1, e2) record, written once
// over an operations type: ScalarOps for one ray (every kernel on both backends), the SSE2 ops
// for four triangles against one ray (leaf_triangles_simd.h), and the packet walk's ops for one
// triangle against a group of rays (kd_packet_walk.inc). Every instantiation performs the same
// IEEE operations in the same order (glm's cross and dot orders; no fused multiply-add), so all
// give the scalar test's t, u, v bit for bit. Negated comparisons keep NaN coordinates and
// zero-area triangles from ever reporting a hit.
//
// Ops: V (a float per lane) and M (a verdict per lane); add, sub, mul, div, set1, zero; the
// comparisons ge, le, gt, lt and neq (true when unordered) giving M; and_ of two M; movemask(M)
// nonzero when any lane is set.
#include "formats/host_device.h"

// Always inlined on the host too: the packet walk instantiates it with AVX2 and AVX-512 operations
// inside functions compiled for those sets, and only inlined does its body take their target.
#if defined(__CUDACC__)
#define KDPM_MT_INLINE KDPM_INLINE
#else
#define KDPM_MT_INLINE inline __attribute__((always_inline))
#endif

namespace kdpm {

// The one-ray operations: a lane is a float, a verdict a bool.
struct ScalarOps {
    using V = float;
    using M = bool;
    KDPM_HD static float add(float a, float b) { return a + b; }
    KDPM_HD static float sub(float a, float b) { return a - b; }
    KDPM_HD static float mul(float a, float b) { return a * b; }
    KDPM_HD static float div(float a, float b) { return a / b; }
    KDPM_HD static float set1(float a) { return a; }
    KDPM_HD static float zero() { return 0.0f; }
    KDPM_HD static bool ge(float a, float b) { return a >= b; }
    KDPM_HD static bool le(float a, float b) { return a <= b; }
    KDPM_HD static bool gt(float a, float b) { return a > b; }
    KDPM_HD static bool lt(float a, float b) { return a < b; }
    KDPM_HD static bool neq(float a, float b) { return a != b; }
    KDPM_HD static bool and_(bool a, bool b) { return a && b; }
    KDPM_HD static int movemask(bool m) { return m ? 1 : 0; }
};

template <class Ops>
struct TriangleTest {
    typename Ops::M hit;  // the lanes hit with t in (tmin, tmax)
    typename Ops::V t, u, v;
};

// The triangle (v0, e1, e2) against the rays (origin, direction) of the lanes in `lanes`, per
// lane. kEarlyOut returns as soon as no lane can hit (branches: one ray, coherent packets);
// without it every lane runs the whole arithmetic (branch-free: a leaf against an incoherent ray).
// t, u, v are meaningful in the hit lanes only.
// Never called out of line, so the calling convention of AVX vectors (-Wpsabi) does not arise.
#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
template <class Ops, bool kEarlyOut>
KDPM_HD KDPM_MT_INLINE TriangleTest<Ops> moller_trumbore(const typename Ops::V (&v0)[3], const typename Ops::V (&e1)[3],
                                                      const typename Ops::V (&e2)[3],
                                                      const typename Ops::V (&origin)[3],
                                                      const typename Ops::V (&direction)[3], typename Ops::V tmin,
                                                      typename Ops::V tmax, typename Ops::M lanes) {
    using V = typename Ops::V;
    const V(&d)[3] = direction;
    const V zero = Ops::zero(), one = Ops::set1(1.0f);
    TriangleTest<Ops> r{lanes, zero, zero, zero};
    // p = cross(d, e2), det = dot(e1, p)
    const V px = Ops::sub(Ops::mul(d[1], e2[2]), Ops::mul(e2[1], d[2]));
    const V py = Ops::sub(Ops::mul(d[2], e2[0]), Ops::mul(e2[2], d[0]));
    const V pz = Ops::sub(Ops::mul(d[0], e2[1]), Ops::mul(e2[0], d[1]));
    const V det = Ops::add(Ops::add(Ops::mul(e1[0], px), Ops::mul(e1[1], py)), Ops::mul(e1[2], pz));
    r.hit = Ops::and_(r.hit, Ops::neq(det, zero));  // parallel or degenerate fail here, NaN later
    if constexpr (kEarlyOut)
        if (Ops::movemask(r.hit) == 0) return r;
    const V inv_det = Ops::div(one, det);
    const V sx = Ops::sub(origin[0], v0[0]), sy = Ops::sub(origin[1], v0[1]), sz = Ops::sub(origin[2], v0[2]);
    r.u = Ops::mul(Ops::add(Ops::add(Ops::mul(sx, px), Ops::mul(sy, py)), Ops::mul(sz, pz)), inv_det);
    r.hit = Ops::and_(r.hit, Ops::and_(Ops::ge(r.u, zero), Ops::le(r.u, one)));
    if constexpr (kEarlyOut)
        if (Ops::movemask(r.hit) == 0) return r;
    // q = cross(s, e1)
    const V qx = Ops::sub(Ops::mul(sy, e1[2]), Ops::mul(e1[1], sz));
    const V qy = Ops::sub(Ops::mul(sz, e1[0]), Ops::mul(e1[2], sx));
    const V qz = Ops::sub(Ops::mul(sx, e1[1]), Ops::mul(e1[0], sy));
    r.v = Ops::mul(Ops::add(Ops::add(Ops::mul(d[0], qx), Ops::mul(d[1], qy)), Ops::mul(d[2], qz)), inv_det);
    r.hit = Ops::and_(r.hit, Ops::and_(Ops::ge(r.v, zero), Ops::le(Ops::add(r.u, r.v), one)));
    if constexpr (kEarlyOut)
        if (Ops::movemask(r.hit) == 0) return r;
    r.t = Ops::mul(Ops::add(Ops::add(Ops::mul(e2[0], qx), Ops::mul(e2[1], qy)), Ops::mul(e2[2], qz)), inv_det);
    r.hit = Ops::and_(r.hit, Ops::and_(Ops::gt(r.t, tmin), Ops::lt(r.t, tmax)));
    return r;
}
#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__)
#pragma GCC diagnostic pop
#endif

}  // namespace kdpm
