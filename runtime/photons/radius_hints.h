#pragma once
// Search radii from the queries just made, for the next one nearby: if k photons lie within r of
// a point p, they lie within r + |q - p| of q, so that bounds q's k-th distance (exactly for the
// same filter and a sphere; a flattened search or another surface normal may need more, which
// estimate_radiance's second search covers). The smallest bound over the last few queries: in
// an 8-pixel-wide tile those are the pixel to the left and the row above.
//
// Only queries on the same surface give bounds: the photon filter follows the surface normal, so
// a neighbour across an edge accepts other photons and its bound often fails. A failed hint
// costs the search done twice.
#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "formats/host_device.h"

#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
#include <emmintrin.h>
#endif

namespace kdpm {

struct RadiusHints {
    static constexpr std::uint32_t kRemembered = 8;
    // Normals at least this aligned (about 2.6 degrees) count as the same surface: a looser
    // cutoff leaves more hints failing, and a stricter one loosens the bounds more than it saves.
    static constexpr float kSameSurfaceCos = 0.999f;
    float px[kRemembered], py[kRemembered], pz[kRemembered], radius[kRemembered];
    float nx[kRemembered], ny[kRemembered], nz[kRemembered];
    std::uint32_t count = 0, next = 0;

    // For a search with the surface filter: the least bound at q over the remembered queries
    // whose normal is within kSameSurfaceCos of n; 0 (no hint) when there is none.
    KDPM_HD float hint(glm::vec3 q, glm::vec3 n) const { return least_bound(q, n, true); }
    // For a search without a filter, where every remembered query's bound holds.
    KDPM_HD float hint(glm::vec3 q) const { return least_bound(q, glm::vec3(0.0f), false); }

    // A query at p with normal n whose k-th photon lay at distance r (only when it found all k).
    KDPM_HD void remember(glm::vec3 p, glm::vec3 n, float r) {
        px[next] = p.x;
        py[next] = p.y;
        pz[next] = p.z;
        nx[next] = n.x;
        ny[next] = n.y;
        nz[next] = n.z;
        radius[next] = r;
        next = next + 1 == kRemembered ? 0 : next + 1;
        if (count < kRemembered) ++count;
    }
    // The same for a search without a filter (no surface: it serves only hint(q)).
    KDPM_HD void remember(glm::vec3 p, float r) { remember(p, glm::vec3(0.0f), r); }

private:
    KDPM_HD float least_bound(glm::vec3 q, glm::vec3 n, bool same_surface) const {
        constexpr float kNone = 3.402823466e38f;
#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
        // The same bounds four at a time (one square root instruction for four), once full.
        if (count == kRemembered) {
            const __m128 qx = _mm_set1_ps(q.x), qy = _mm_set1_ps(q.y), qz = _mm_set1_ps(q.z);
            const __m128 mx = _mm_set1_ps(n.x), my = _mm_set1_ps(n.y), mz = _mm_set1_ps(n.z);
            const __m128 same = _mm_set1_ps(kSameSurfaceCos), none = _mm_set1_ps(kNone);
            const __m128 every = _mm_castsi128_ps(_mm_set1_epi32(-1));
            __m128 least = none;
            for (std::uint32_t i = 0; i < kRemembered; i += 4) {
                const __m128 dx = _mm_sub_ps(qx, _mm_loadu_ps(px + i)), dy = _mm_sub_ps(qy, _mm_loadu_ps(py + i)),
                             dz = _mm_sub_ps(qz, _mm_loadu_ps(pz + i));
                const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
                const __m128 cos = _mm_add_ps(
                    _mm_add_ps(_mm_mul_ps(mx, _mm_loadu_ps(nx + i)), _mm_mul_ps(my, _mm_loadu_ps(ny + i))),
                    _mm_mul_ps(mz, _mm_loadu_ps(nz + i)));
                const __m128 bound = _mm_add_ps(_mm_loadu_ps(radius + i), _mm_sqrt_ps(d2));
                const __m128 kept = same_surface ? _mm_cmpge_ps(cos, same) : every;
                // A NaN bound (second operand of min) leaves the least as it was, as the scalar loop does.
                least = _mm_min_ps(_mm_or_ps(_mm_and_ps(kept, bound), _mm_andnot_ps(kept, none)), least);
            }
            least = _mm_min_ps(least, _mm_shuffle_ps(least, least, _MM_SHUFFLE(1, 0, 3, 2)));
            least = _mm_min_ps(least, _mm_shuffle_ps(least, least, _MM_SHUFFLE(2, 3, 0, 1)));
            const float best = _mm_cvtss_f32(least);
            return best < kNone ? best : 0.0f;
        }
#endif
        float best = kNone;
        for (std::uint32_t i = 0; i < count; ++i) {
            if (same_surface && !(n.x * nx[i] + n.y * ny[i] + n.z * nz[i] >= kSameSurfaceCos)) continue;
            const float dx = q.x - px[i], dy = q.y - py[i], dz = q.z - pz[i];
            const float bound = radius[i] + sqrtf(dx * dx + dy * dy + dz * dz);
            if (bound < best) best = bound;
        }
        return best < kNone ? best : 0.0f;
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
