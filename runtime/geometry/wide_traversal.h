#pragma once
// Closest hit and any-hit over the wide tree (formats/wide_layout.h, geometry.wide): each step
// tests a node's eight child boxes at once (AVX2 where the CPU has it, chosen at run time; lane
// by lane elsewhere), visits the entered children near to far and skips those that start beyond
// the nearest hit so far. The boxes lie in disjoint kd cells (but for their small margin), so the
// leaves visited first are the ones the binary walk would visit, without its empty leaves and
// the planes between them. The same triangle tests run on the same leaves' triangles, so the hits
// are the binary walk's, except that ties at one t may name the other triangle and that a ray
// lying in a kd plane can find a hit there that the binary walk misses (brute force finds it).
#include <cmath>
#include <cstdint>

#include "formats/host_device.h"
#include "formats/wide_layout.h"
#include "runtime/geometry/box_exit_slack.h"
#include "runtime/geometry/cpu_features.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/geometry/leaf_triangles_simd.h"
#include "runtime/geometry/ray.h"
#include "runtime/geometry/triangle_intersect.h"

#if defined(__x86_64__) && !defined(__CUDACC__)
#include <immintrin.h>
#define KDPM_WIDE_AVX2 1
#endif

namespace kdpm {

namespace wide_detail {

using kdpm::kExitSlack;  // runtime/geometry/box_exit_slack.h

// A direction component of (nearly) zero as a tiny one of the same sign: the box test's 1/d stays
// finite and (box - origin) * (1/d) never 0 * inf. The tilt it makes is far below the margin
// the boxes carry (wide_box_margin).
inline float safe_direction(float d) {
    constexpr float kTiny = 1e-20f;
    return std::fabs(d) < kTiny ? std::copysign(kTiny, d) : d;
}

namespace scalar {

struct B {
    struct Ray {
        float org[3], inv[3];
        int near_hi[3];  // 1 where the direction is negative: the near face is hi
    };
    static Ray prepare(const kdpm::Ray& ray) {
        Ray r;
        for (int a = 0; a < 3; ++a) {
            r.org[a] = ray.origin[a];
            r.inv[a] = 1.0f / safe_direction(ray.direction[a]);
            r.near_hi[a] = r.inv[a] < 0.0f;
        }
        return r;
    }
    static int enter(const WideNode& n, const Ray& r, float tmin, float tmax, float (&tnear)[kWideWidth]) {
        int hits = 0;
        for (std::uint32_t j = 0; j < kWideWidth; ++j) {
            float t0 = tmin, t1 = tmax;
            for (int a = 0; a < 3; ++a) {
                const float near = r.near_hi[a] ? n.hi[a][j] : n.lo[a][j];
                const float far = r.near_hi[a] ? n.lo[a][j] : n.hi[a][j];
                t0 = std::fmax(t0, (near - r.org[a]) * r.inv[a]);
                t1 = std::fmin(t1, (far - r.org[a]) * r.inv[a]);
            }
            tnear[j] = t0;
            hits |= (t0 <= t1 * kExitSlack) << j;
        }
        return hits;
    }
};

#include "runtime/geometry/wide_walk.inc"

}  // namespace scalar

#if defined(KDPM_WIDE_AVX2)
KDPM_BEGIN_TARGET("avx2")
namespace avx2 {

struct B {
    struct Ray {
        __m256 org[3], inv[3];
        int near_hi[3];
    };
    static Ray prepare(const kdpm::Ray& ray) {
        Ray r;
        for (int a = 0; a < 3; ++a) {
            const float inv = 1.0f / safe_direction(ray.direction[a]);
            r.inv[a] = _mm256_set1_ps(inv);
            r.org[a] = _mm256_set1_ps(ray.origin[a]);
            r.near_hi[a] = inv < 0.0f;
        }
        return r;
    }
    static int enter(const WideNode& n, const Ray& r, float tmin, float tmax, float (&tnear)[kWideWidth]) {
        __m256 t0 = _mm256_set1_ps(tmin), t1 = _mm256_set1_ps(tmax);
        for (int a = 0; a < 3; ++a) {
            const float* near = r.near_hi[a] ? n.hi[a] : n.lo[a];
            const float* far = r.near_hi[a] ? n.lo[a] : n.hi[a];
            t0 = _mm256_max_ps(t0, _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(near), r.org[a]), r.inv[a]));
            t1 = _mm256_min_ps(t1, _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(far), r.org[a]), r.inv[a]));
        }
        _mm256_store_ps(tnear, t0);
        return _mm256_movemask_ps(_mm256_cmp_ps(t0, _mm256_mul_ps(t1, _mm256_set1_ps(kExitSlack)), _CMP_LE_OQ));
    }
};

#include "runtime/geometry/wide_walk.inc"

}  // namespace avx2
KDPM_END_TARGET
#endif

}  // namespace wide_detail

// The closest hit with t in (ray.tmin, ray.tmax) over g.wide (which must be set).
inline Hit closest_hit_wide(const GeometryView& g, const Ray& ray) {
#if defined(KDPM_WIDE_AVX2)
    if (cpu_has_avx2()) return wide_detail::avx2::closest_hit(g, ray);
#endif
    return wide_detail::scalar::closest_hit(g, ray);
}

// Whether any triangle is hit with t in (ray.tmin, ray.tmax), over g.wide.
inline bool occluded_wide(const GeometryView& g, const Ray& ray) {
#if defined(KDPM_WIDE_AVX2)
    if (cpu_has_avx2()) return wide_detail::avx2::occluded(g, ray);
#endif
    return wide_detail::scalar::occluded(g, ray);
}

}  // namespace kdpm
