#pragma once
// Search radii from the queries just made, for the next one nearby: if k photons lie within r of
// a point p, they lie within r + |q - p| of q, so that bounds q's k-th distance (exactly for the
// same filter and a sphere; a flattened search or another surface normal may need more, which
// estimate_radiance's second search covers). The smallest bound over the last few queries: in
// an 8-pixel-wide tile those are the pixel to the left and the row above.
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"

#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
#include <xmmintrin.h>
#endif

namespace kdpm {

struct RadiusHints {
    static constexpr std::uint32_t kRemembered = 8;
    float px[kRemembered], py[kRemembered], pz[kRemembered], radius[kRemembered];
    std::uint32_t count = 0, next = 0;

    // 0 (no hint) until a query has been remembered.
    KDPM_HD float hint(glm::vec3 q) const {
#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
        // The same bounds four at a time (one square root instruction for four), once full.
        if (count == kRemembered) {
            const __m128 qx = _mm_set1_ps(q.x), qy = _mm_set1_ps(q.y), qz = _mm_set1_ps(q.z);
            __m128 least = _mm_set1_ps(3.402823466e38f);
            for (std::uint32_t i = 0; i < kRemembered; i += 4) {
                const __m128 dx = _mm_sub_ps(qx, _mm_loadu_ps(px + i)), dy = _mm_sub_ps(qy, _mm_loadu_ps(py + i)),
                             dz = _mm_sub_ps(qz, _mm_loadu_ps(pz + i));
                const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
                least = _mm_min_ps(least, _mm_add_ps(_mm_loadu_ps(radius + i), _mm_sqrt_ps(d2)));
            }
            least = _mm_min_ps(least, _mm_shuffle_ps(least, least, _MM_SHUFFLE(1, 0, 3, 2)));
            least = _mm_min_ps(least, _mm_shuffle_ps(least, least, _MM_SHUFFLE(2, 3, 0, 1)));
            return _mm_cvtss_f32(least);
        }
#endif
        float best = 0.0f;
        for (std::uint32_t i = 0; i < count; ++i) {
            const float dx = q.x - px[i], dy = q.y - py[i], dz = q.z - pz[i];
            const float bound = radius[i] + sqrtf(dx * dx + dy * dy + dz * dz);
            if (best == 0.0f || bound < best) best = bound;
        }
        return best;
    }

    // A query at p whose k-th photon lay at distance r (only when it found all k).
    KDPM_HD void remember(glm::vec3 p, float r) {
        px[next] = p.x;
        py[next] = p.y;
        pz[next] = p.z;
        radius[next] = r;
        next = next + 1 == kRemembered ? 0 : next + 1;
        if (count < kRemembered) ++count;
    }
};

// A k-nearest search started from a hint: search(limit) is a k-nearest search out to `limit`
// (<= 0: unlimited) that returns how many it found. When radius_hint is tighter than max_radius
// the search first runs out to the hint, which prunes most of the tree before the first k
// photons are found, and runs again out to max_radius only when that found fewer than k. Either
// way the k nearest are found: a search limited to r that finds k photons has found the k
// nearest overall.
template <class Search>
KDPM_HD std::uint32_t search_from_hint(const Search& search, std::uint32_t k, float radius_hint, float max_radius) {
    const bool tighter = radius_hint > 0.0f && (max_radius <= 0.0f || radius_hint < max_radius);
    const std::uint32_t found = search(tighter ? radius_hint : max_radius);
    return tighter && found < k ? search(max_radius) : found;
}

}  // namespace kdpm
