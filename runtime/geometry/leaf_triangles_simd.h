#pragma once
// A leaf's triangles against one ray, four at a time (SSE2, CPU only). The single-ray walk's
// leaf loop tests one triangle after another, and for incoherent rays (photon paths, bounces)
// each test's early exits are branches the CPU cannot predict; here every lane runs the whole of
// moller_trumbore.h's arithmetic without its early outs, and only the lanes' verdicts are read.
// The results are the scalar loop's bit for bit: the closest hit is the lowest t, the first of
// the leaf's order among equal t (the scalar loop replaces a hit only with a strictly nearer
// one), with that triangle's u and v.
#include <cstddef>
#include <cstdint>

#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/ray.h"

#include "runtime/geometry/moller_trumbore.h"
#include "runtime/geometry/sse2_ops.h"

#if defined(KDPM_SSE2_OPS)
#define KDPM_LEAF_SIMD 1
#endif

namespace kdpm {

#if defined(KDPM_LEAF_SIMD)
namespace leaf_simd_detail {

// intersect_triangle for the triangles a[0..3] and one ray: the lanes that hit with t in
// (tmin, tmax) as bits 0..3, and their t, u, v.
struct Lanes4 {
    int hits;
    alignas(16) float t[4], u[4], v[4];
};

// The transposes below read a TriangleRecord as three rows of four: (v0, material), (e1, source),
// (e2, flags).
static_assert(offsetof(TriangleRecord, v0) == 0 && offsetof(TriangleRecord, e1) == 16 &&
                  offsetof(TriangleRecord, e2) == 32 && sizeof(TriangleRecord) == 48,
              "leaf_triangles_simd.h loads TriangleRecord rows of four floats");

inline void intersect4(const TriangleRecord* const a[4], const Ray& ray, float tmax, Lanes4& out) {
    const float* r0 = reinterpret_cast<const float*>(a[0]);
    const float* r1 = reinterpret_cast<const float*>(a[1]);
    const float* r2 = reinterpret_cast<const float*>(a[2]);
    const float* r3 = reinterpret_cast<const float*>(a[3]);
    __m128 v0x = _mm_loadu_ps(r0), v0y = _mm_loadu_ps(r1), v0z = _mm_loadu_ps(r2), v0w = _mm_loadu_ps(r3);
    _MM_TRANSPOSE4_PS(v0x, v0y, v0z, v0w);
    __m128 e1x = _mm_loadu_ps(r0 + 4), e1y = _mm_loadu_ps(r1 + 4), e1z = _mm_loadu_ps(r2 + 4), e1w = _mm_loadu_ps(r3 + 4);
    _MM_TRANSPOSE4_PS(e1x, e1y, e1z, e1w);
    __m128 e2x = _mm_loadu_ps(r0 + 8), e2y = _mm_loadu_ps(r1 + 8), e2z = _mm_loadu_ps(r2 + 8), e2w = _mm_loadu_ps(r3 + 8);
    _MM_TRANSPOSE4_PS(e2x, e2y, e2z, e2w);

    const __m128 v0[3] = {v0x, v0y, v0z}, e1[3] = {e1x, e1y, e1z}, e2[3] = {e2x, e2y, e2z};
    const __m128 o[3] = {_mm_set1_ps(ray.origin.x), _mm_set1_ps(ray.origin.y), _mm_set1_ps(ray.origin.z)};
    const __m128 d[3] = {_mm_set1_ps(ray.direction.x), _mm_set1_ps(ray.direction.y), _mm_set1_ps(ray.direction.z)};
    const __m128 all = _mm_castsi128_ps(_mm_set1_epi32(-1));
    const TriangleTest<Sse2Ops> r =
        moller_trumbore<Sse2Ops, false>(v0, e1, e2, o, d, _mm_set1_ps(ray.tmin), _mm_set1_ps(tmax), all);
    out.hits = _mm_movemask_ps(r.hit);
    _mm_store_ps(out.t, r.t);
    _mm_store_ps(out.u, r.u);
    _mm_store_ps(out.v, r.v);
}

// The leaf's triangles in groups of four, in leaf order: on_group(index, lanes) for each, with
// t limited by limit() as it is when the group is tested; stops when on_group returns true.
// Lanes past the leaf's end repeat the group's last triangle: it is already loaded, and a
// repeat can neither add a verdict nor win a tie against the lane it repeats (a hit must be
// strictly nearer to replace one).
template <class Limit, class OnGroup>
inline bool each_group(const GeometryView& g, const Ray& ray, std::uint32_t first, std::uint32_t count,
                       const Limit& limit, const OnGroup& on_group) {
    for (std::uint32_t base = 0; base < count; base += 4) {
        const std::uint32_t m = count - base < 4 ? count - base : 4;
        std::uint32_t index[4];
        const TriangleRecord* tri[4];
        for (std::uint32_t j = 0; j < 4; ++j) {
            index[j] = g.leaf_indices[first + base + (j < m ? j : m - 1)];
            tri[j] = &g.triangles[index[j]];
        }
        Lanes4 lanes;
        intersect4(tri, ray, limit(), lanes);
        if (on_group(index, lanes)) return true;
    }
    return false;
}

}  // namespace leaf_simd_detail

// The scalar leaf loop's closest hit over leaf_indices[first, first + count), into `hit` (its t
// is the current limit).
inline void closest_in_leaf(const GeometryView& g, const Ray& ray, std::uint32_t first, std::uint32_t count,
                            Hit& hit) {
    using namespace leaf_simd_detail;
    each_group(g, ray, first, count, [&] { return hit.t; }, [&](const std::uint32_t(&index)[4], const Lanes4& r) {
        // In leaf order, each against the nearest so far: the scalar loop's rule.
        for (int lanes = r.hits; lanes != 0; lanes &= lanes - 1) {
            const int j = __builtin_ctz(static_cast<unsigned>(lanes));
            if (r.t[j] < hit.t) hit = Hit{r.t[j], index[j], r.u[j], r.v[j]};
        }
        return false;
    });
}

// Whether any triangle of the leaf is hit with t in (ray.tmin, ray.tmax).
inline bool any_in_leaf(const GeometryView& g, const Ray& ray, std::uint32_t first, std::uint32_t count) {
    using namespace leaf_simd_detail;
    return each_group(g, ray, first, count, [&] { return ray.tmax; },
                      [](const std::uint32_t(&)[4], const Lanes4& r) { return r.hits != 0; });
}
#endif

}  // namespace kdpm
