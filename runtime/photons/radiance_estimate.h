#pragma once
// The photon map radiance estimate at a diffuse surface point (Jensen):
//   L = sum over the k nearest photons of  f_r * power * w  /  (pi r^2 * norm)
// with f_r = albedo / pi, r the distance to the k-th photon (or the maximum radius when fewer
// were found within it), and w a cone filter weight (1 - d / (cone_k r), norm 1 - 2 / (3 cone_k))
// when enabled. With fixed_radius, the sum runs over every photon within r = max_radius instead
// (the fixed-radius estimate of progressive photon mapping). Against light leaks, photons whose stored normal disagrees with the surface
// normal, or that arrived from behind the surface, are skipped, and the search may be
// flattened toward the surface (DiscMetric).
#include <cstdint>
#include <cstring>

#include <glm/glm.hpp>

#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
#include <xmmintrin.h>
#endif

#include "formats/host_device.h"
#include "formats/photon_layout.h"
#include "runtime/photons/filter_memo.h"
#include "runtime/photons/knn_search.h"
#include "runtime/photons/node_vector_bounds.h"
#include "runtime/photons/radius_hints.h"
#include "runtime/photons/radius_search.h"
#include "runtime/shading/constants.h"
#include "runtime/shading/diffuse.h"

namespace kdpm {

struct RadianceEstimateParams {
    std::uint32_t k = 32;          // photons per estimate, 1..kMaxGatherK
    float max_radius = 0.0f;       // <= 0: unlimited
    bool cone_filter = false;
    float cone_k = 1.1f;           // cone slope (>= 1)
    float min_normal_cos = 0.7f;   // stored normal . surface normal must reach this (-1 disables)
    float flatten = 0.0f;          // DiscMetric flattening (0: a sphere)
    std::uint32_t min_bounce = 0;  // 1 for "direct + photons": skip the direct-light hits
    std::uint32_t exclude_flags = 0;  // e.g. kPhotonCaustic when the caustic map is gathered separately
    bool fixed_radius = false;     // every photon within max_radius (> 0) instead of the k nearest
    float plane_distance = 0.0f;   // > 0: only photons this close to the surface's tangent plane (OnPlaneFilter)
};

struct RadianceEstimate {
    glm::vec3 radiance{0.0f};  // outgoing radiance toward the viewer (W / (m^2 sr))
    float radius = 0.0f;       // search radius used
    std::uint32_t count = 0;   // photons found
};

// Photons that may light this surface point (see the file comment).
//
// Most candidates are decided far from the thresholds, so each test first looks at the folded
// octahedral vector before normalization (no divisions, no square root): its direction is
// decode_octahedral's to within ~1e-6, and a decision taken only outside a margin of 1e-4 (sign
// test) or 1e-3 (cosine test, on squares) is the one the exact decoding takes. Inside the
// margin, or for an unusual normal or threshold, the exact decoding decides, so the accepted
// set is exactly that of decoding every photon.
struct SurfacePhotonFilter {
    const std::uint32_t* flags;
    const PackedPhotonDirections* directions;
    const float* unpacked;  // PhotonMapView::unpacked: when set, the decoded vectors are read
    std::uint64_t stride;   // PhotonMapView::photon_count: from one of unpacked's arrays to the next
    glm::vec3 normal;
    float min_normal_cos;
    std::uint32_t min_bounce;
    std::uint32_t exclude_flags;
    bool check_flags;  // false when no flag or bounce can reject (skips a load per photon)
    bool quick;        // the margins hold: |normal| ~ 1 and min_normal_cos in [0.05, 1]
    float cos2_above, cos2_below;  // min_normal_cos^2 +- 1e-3: the cosine test's margins, once per query
    const float* bounds;  // PhotonMapView::vector_bounds, used when node_test
    bool node_test;       // rejects_node may rule nodes out: bounds set, |normal| ~ 1

    KDPM_HD SurfacePhotonFilter(const PhotonMapView& map, glm::vec3 n, float min_cos, std::uint32_t min_bounce_,
                                std::uint32_t exclude)
        : flags(map.flags), directions(map.directions), unpacked(map.unpacked), stride(map.photon_count), normal(n),
          min_normal_cos(min_cos),
          min_bounce(min_bounce_), exclude_flags(exclude), check_flags(min_bounce_ > 0 || exclude != 0),
          bounds(map.vector_bounds) {
        const float n2 = n.x * n.x + n.y * n.y + n.z * n.z;
        const bool unit = n2 > 0.999f && n2 < 1.001f;
        quick = unit && (min_cos <= -1.0f || (min_cos >= 0.05f && min_cos <= 1.0f));
        node_test = bounds != nullptr && unit;
        const float c2 = min_cos * min_cos;
        cos2_above = c2 + 1e-3f;
        cos2_below = c2 - 1e-3f;
    }

    // The octahedral vector as decode_octahedral folds it, unnormalized; the snorm16s read by a
    // reciprocal multiply, not decode's division (within an ulp, and this decides only outside
    // the margin).
    KDPM_HD static void unfolded(std::uint32_t packed, float out[3]) {
        constexpr float kInv = 1.0f / 32767.0f;
        const float u = static_cast<float>(static_cast<std::int16_t>(static_cast<std::uint16_t>(packed & 0xffffu))) * kInv;
        const float v = static_cast<float>(static_cast<std::int16_t>(static_cast<std::uint16_t>(packed >> 16))) * kInv;
        octahedral_unfold(u < -1.0f ? -1.0f : u, v < -1.0f ? -1.0f : v, out);
    }

    KDPM_HD bool exact(std::uint32_t p) const {
        if (unpacked) {
            const float d[3] = {unpacked[p], unpacked[stride + p], unpacked[2 * stride + p]};
            const float nn[3] = {unpacked[3 * stride + p], unpacked[4 * stride + p], unpacked[5 * stride + p]};
            return exact_from(d, nn);
        }
        float d[3], nn[3];
        decode_octahedral(directions[p].direction, d);
        if (d[0] * normal.x + d[1] * normal.y + d[2] * normal.z >= 0.0f) return false;  // from behind
        if (min_normal_cos <= -1.0f) return true;
        decode_octahedral(directions[p].normal, nn);
        return nn[0] * normal.x + nn[1] * normal.y + nn[2] * normal.z >= min_normal_cos;
    }

    // exact() from the decoded direction d and surface normal nn.
    KDPM_HD bool exact_from(const float* d, const float* nn) const {
        if (d[0] * normal.x + d[1] * normal.y + d[2] * normal.z >= 0.0f) return false;  // from behind
        if (min_normal_cos <= -1.0f) return true;
        return nn[0] * normal.x + nn[1] * normal.y + nn[2] * normal.z >= min_normal_cos;
    }

    // False when the photon's flags or bounce rule it out.
    KDPM_HD bool passes_flags(std::uint32_t p) const {
        if (!check_flags) return true;
        const std::uint32_t f = flags[p];
        return (f & exclude_flags) == 0 && photon_bounce(f) >= min_bounce;
    }

    // The quick decision from the photon's unfolded direction r and, when given, its unfolded
    // normal (else decoded here if needed); only for a filter that is quick.
    KDPM_HD bool decide_unfolded(std::uint32_t p, const float r[3], const float* unfolded_normal) const {
        const float s = r[0] * normal.x + r[1] * normal.y + r[2] * normal.z;
        if (s >= 1e-4f) return false;  // from behind
        if (s > -1e-4f) return exact(p);
        if (min_normal_cos <= -1.0f) return true;
        float decoded[3];
        const float* m = unfolded_normal;
        if (m == nullptr) {
            unfolded(directions[p].normal, decoded);
            m = decoded;
        }
        const float c = m[0] * normal.x + m[1] * normal.y + m[2] * normal.z;
        if (c <= 0.0f) return false;  // min_normal_cos >= 0.05 here
        const float l2 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
        if (c * c > cos2_above * l2) return true;
        if (c * c < cos2_below * l2) return false;
        return exact(p);
    }

    KDPM_HD bool operator()(std::uint32_t p) const {
        if (!passes_flags(p)) return false;
        if (!quick || unpacked) return exact(p);  // decoded already: the exact test is the cheap one
        float r[3];
        unfolded(directions[p].direction, r);
        return decide_unfolded(p, r, nullptr);
    }

    // True when no photon below `node` can pass, from the node's boxes of decoded directions and
    // normals and its flag summary (vector_bounds): every photon fails the flag rules, or the
    // least direction . normal over the box is not below zero (all from behind), or the greatest
    // stored normal . normal is below min_normal_cos. The boxes' sums and the photons' differ by
    // a few float roundings (~1e-6 for unit vectors); a margin of 1e-4 keeps every node that may
    // hold an accepted photon. NaN sums rule nothing out.
    KDPM_HD bool rejects_node(std::uint32_t node) const {
        if (!node_test) return false;
        constexpr float kMargin = 1e-4f;
        const float* b = bounds + static_cast<std::uint64_t>(node) * kVectorBoundFloats;
        // Every photon below is of a lower bounce, or carries a flag this filter excludes.
        if (check_flags && (b[kMaxBounceAt] < static_cast<float>(min_bounce) ||
                            (static_cast<std::uint32_t>(b[kCommonFlagsAt]) & exclude_flags) != 0))
            return true;
#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
        const __m128 nv = _mm_setr_ps(normal.x, normal.y, normal.z, 0.0f);
        const __m128 least = _mm_min_ps(_mm_mul_ps(_mm_loadu_ps(b), nv), _mm_mul_ps(_mm_loadu_ps(b + 4), nv));
        const __m128 most = _mm_max_ps(_mm_mul_ps(_mm_loadu_ps(b + 8), nv), _mm_mul_ps(_mm_loadu_ps(b + 12), nv));
        // Lanes 0..2 summed (lane 3, the flag summary times 0, is not read): along = least's sum,
        // facing = most's sum.
        const __m128 lo = _mm_unpacklo_ps(least, most), hi = _mm_unpackhi_ps(least, most);  // l0 m0 l1 m1 | l2 m2 0 0
        const __m128 sums = _mm_add_ps(_mm_add_ps(lo, _mm_movehl_ps(lo, lo)), hi);        // l0+l1+l2, m0+m1+m2
        const float along = _mm_cvtss_f32(sums);
        const float facing = _mm_cvtss_f32(_mm_shuffle_ps(sums, sums, _MM_SHUFFLE(1, 1, 1, 1)));
#else
        const float n[3] = {normal.x, normal.y, normal.z};
        float along = 0.0f, facing = 0.0f;
        for (int a = 0; a < 3; ++a) {
            const float l = n[a] * b[a], h = n[a] * b[4 + a], sl = n[a] * b[8 + a], sh = n[a] * b[12 + a];
            along += l < h ? l : h;
            facing += sl > sh ? sl : sh;
        }
#endif
        if (along >= kMargin) return true;
        return min_normal_cos > -1.0f && facing < min_normal_cos - kMargin;
    }

    // Sixteen decisions at once (knn_search's AcceptsSixteen), from the decoded vectors only.
    KDPM_HD bool batched() const { return unpacked != nullptr; }

    // Bit j set when photon base + j passes (operator()); base + 16 <= photon_count, unpacked set.
    // The SSE2 lanes compute exact_from's sums in its order, so the same floats are compared.
    KDPM_HD std::uint32_t accepted16(std::uint32_t base) const {
        std::uint32_t mask = 0;
#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
        const __m128 n0 = _mm_set1_ps(normal.x), n1 = _mm_set1_ps(normal.y), n2 = _mm_set1_ps(normal.z);
        const __m128 zero = _mm_setzero_ps(), cos_min = _mm_set1_ps(min_normal_cos);
        const bool any_normal = min_normal_cos <= -1.0f;
        const float* d = unpacked + base;
        for (std::uint32_t i = 0; i < 16; i += 4) {
            const __m128 along = dot4(d + i, n0, n1, n2);
            __m128 ok = _mm_cmpnge_ps(along, zero);  // not from behind (as exact_from: NaN passes)
            if (!any_normal) ok = _mm_and_ps(ok, _mm_cmpge_ps(dot4(d + 3 * stride + i, n0, n1, n2), cos_min));
            mask |= static_cast<std::uint32_t>(_mm_movemask_ps(ok)) << i;
        }
#else
        for (std::uint32_t j = 0; j < 16; ++j) mask |= static_cast<std::uint32_t>(exact(base + j)) << j;
#endif
        if (check_flags)
            for (std::uint32_t j = 0; j < 16; ++j)
                mask &= ~(static_cast<std::uint32_t>(!passes_flags(base + j)) << j);
        return mask;
    }

private:
#if defined(__SSE2__) && !defined(__CUDA_ARCH__)
    // v . n for 4 photons: v's x, y, z arrays start at v, v + stride, v + 2 stride.
    __m128 dot4(const float* v, __m128 n0, __m128 n1, __m128 n2) const {
        const __m128 xy = _mm_add_ps(_mm_mul_ps(_mm_loadu_ps(v), n0), _mm_mul_ps(_mm_loadu_ps(v + stride), n1));
        return _mm_add_ps(xy, _mm_mul_ps(_mm_loadu_ps(v + 2 * stride), n2));
    }
#endif
};

// The plane test of the gather hits' estimates and lookups and of the irradiance map's
// precomputation (RadianceEstimateParams::plane_distance). A photon whose normal agrees may still
// lie on another surface parallel to the query's, a few centimetres off (a slab or ledge over a
// floor, the steps of a moulding); its light is not the query's, and in the shadow under such a
// surface it is far too bright. A photon passes when its height h over the query's tangent plane
// is within max(plane_distance, kPlaneSlope * d), d its distance along the plane: a flat
// neighbour's h is 0, a curved surface's grows as d^2 / 2R (R its radius of curvature, so it
// passes out to d = 2 R kPlaneSlope), a parallel surface's stays at its offset (so it passes only
// beyond offset / kPlaneSlope, farther than the search reaches when the offset is a few photon
// spacings).
inline constexpr float kPlaneDistanceFactor = 0.5f;  // plane_distance over the map's typical 32nd-photon distance
inline constexpr float kPlaneSlope = 0.1f;

// The photons `inner` accepts that pass the plane test through `origin` with unit `normal`.
template <class Inner>
struct OnPlaneFilter {
    Inner inner;
    const float* x;
    const float* y;
    const float* z;
    glm::vec3 origin, normal;
    float max_distance;

    KDPM_HD bool on_plane(std::uint32_t p) const {
        const float dx = x[p] - origin.x, dy = y[p] - origin.y, dz = z[p] - origin.z;
        const float h = dx * normal.x + dy * normal.y + dz * normal.z;
        const float h2 = h * h;
        if (h2 <= max_distance * max_distance) return true;
        // h <= slope * d with d^2 = |delta|^2 - h^2.
        return h2 * (1.0f + kPlaneSlope * kPlaneSlope) <= kPlaneSlope * kPlaneSlope * (dx * dx + dy * dy + dz * dz);
    }
    KDPM_HD bool operator()(std::uint32_t p) const { return on_plane(p) && inner(p); }
    KDPM_HD bool rejects_node(std::uint32_t node) const { return inner.rejects_node(node); }
    KDPM_HD bool batched() const { return inner.batched(); }
    KDPM_HD std::uint32_t accepted16(std::uint32_t base) const {
        std::uint32_t mask = inner.accepted16(base);
        for (std::uint32_t j = 0; j < 16; ++j)
            if (((mask >> j) & 1u) && !on_plane(base + j)) mask &= ~(1u << j);
        return mask;
    }
};

KDPM_HD KDPM_INLINE OnPlaneFilter<SurfacePhotonFilter> on_plane_filter(const PhotonMapView& map, glm::vec3 position,
                                                                       glm::vec3 normal, float min_normal_cos,
                                                                       float max_plane_distance) {
    return {SurfacePhotonFilter(map, normal, min_normal_cos, 0u, 0u), map.x, map.y, map.z, position, normal,
            max_plane_distance};
}

// decode_rgbe's value as a vector.
KDPM_HD KDPM_INLINE glm::vec3 photon_power(std::uint32_t rgbe) {
    const std::uint32_t e = rgbe >> 24;
    if (e == 0) return glm::vec3(0.0f);
    const float scale = rgbe_scale(e);
    return glm::vec3(static_cast<float>(rgbe & 0xffu) * scale, static_cast<float>((rgbe >> 8) & 0xffu) * scale,
                     static_cast<float>((rgbe >> 16) & 0xffu) * scale);
}

// Photon p's power: decoded once already (PhotonMapView::unpacked_power, the same floats) or now.
KDPM_HD KDPM_INLINE glm::vec3 power_of(const PhotonMapView& map, std::uint32_t p) {
    if (map.unpacked_power) {
        const float* v = map.unpacked_power + 3 * static_cast<std::uint64_t>(p);
        return glm::vec3(v[0], v[1], v[2]);
    }
    return photon_power(map.power[p]);
}

// The cone filter's weight of a photon at distance d in a disc of radius r, and its normalisation.
KDPM_HD KDPM_INLINE float cone_weight(float d, float cone_k, float r) {
    const float w = 1.0f - d / (cone_k * r);
    return w < 0.0f ? 0.0f : w;
}
KDPM_HD KDPM_INLINE float cone_norm(float cone_k) { return 1.0f - 2.0f / (3.0f * cone_k); }

// The fixed-radius estimate (params.fixed_radius; the search is a sphere, whatever flatten says).
KDPM_HD inline RadianceEstimate estimate_radiance_in_radius(const PhotonMapView& map, glm::vec3 position,
                                                            glm::vec3 albedo, const RadianceEstimateParams& params,
                                                            const SurfacePhotonFilter& filter) {
    RadianceEstimate out;
    const float r = params.max_radius;
    if (!(r > 0.0f)) return out;
    const float cone_k = params.cone_k < 1.0f ? 1.0f : params.cone_k;
    glm::vec3 flux(0.0f);
    std::uint32_t count = 0;
    radius_search(map, position, r, [&](std::uint32_t p, float d2) {
        if (!filter(p)) return;
        const float w = params.cone_filter ? cone_weight(sqrtf(d2), cone_k, r) : 1.0f;
        flux += w * power_of(map, p);
        ++count;
    });
    out.count = count;
    out.radius = r;
    if (count == 0) return out;
    const float norm = params.cone_filter ? cone_norm(cone_k) : 1.0f;
    out.radiance = lambert_brdf(albedo) * flux / (kPi * (r * r) * norm);
    return out;
}

// The share of the search disc of radius^2 r2 the found photons cover, for an estimate with the
// plane test. Where the surface ends within the disc (an edge, a crease whose other side the
// filters refuse, a column thinner than the disc), the photons' flux spreads over less than
// pi r^2, and dividing by all of it darkens every edge and thin part. The disc is cut into 16
// cells of equal area, 8 sectors about the normal in two rings (the inner one out to r / sqrt 2),
// and the cells holding a photon count; on a surface filling the disc, n photons leave a cell
// empty with probability (15/16)^n, which the share is divided by the expectation of. Fewer
// than 32 photons: 1 (no correction, too coarse).
KDPM_HD inline float covered_share(const PhotonMapView& map, const KnnHeap& heap, std::uint32_t found, glm::vec3 position,
                                   glm::vec3 normal, float r2) {
    if (found < 32 || !(r2 > 0.0f)) return 1.0f;
    glm::vec3 t, b;
    tangent_frame(normal, t, b);
    std::uint32_t cells = 0;
    for (std::uint32_t i = 0; i < found; ++i) {
        const std::uint32_t p = heap.index[i];
        const glm::vec3 d(map.x[p] - position.x, map.y[p] - position.y, map.z[p] - position.z);
        const float u = glm::dot(d, t), v = glm::dot(d, b);
        // The octant of (u, v): the signs, then which is larger; the ring by the distance in the plane.
        const std::uint32_t sector = (u < 0.0f ? 4u : 0u) | (v < 0.0f ? 2u : 0u) | (fabsf(u) < fabsf(v) ? 1u : 0u);
        const std::uint32_t ring = 2.0f * (u * u + v * v) < r2 ? 0u : 8u;
        cells |= 1u << (sector + ring);
    }
    std::uint32_t covered = 0;
    for (std::uint32_t c = 0; c < 16; ++c) covered += (cells >> c) & 1u;
    const float expected = 1.0f - powf(15.0f / 16.0f, static_cast<float>(found));
    const float share = static_cast<float>(covered) / (16.0f * expected);
    return share < 1.0f ? share : 1.0f;
}

// The estimate at (position, normal) from the `found` photons a k-nearest search left in the
// heap (the k-th distance first), as estimate_radiance makes it; with the plane test, over the
// disc's covered share.
KDPM_HD inline RadianceEstimate estimate_from_found(const PhotonMapView& map, const KnnHeap& heap, std::uint32_t found,
                                                    std::uint32_t k, glm::vec3 position, glm::vec3 normal,
                                                    glm::vec3 albedo, const RadianceEstimateParams& params) {
    RadianceEstimate out;
    out.count = found;
    if (found == 0) return out;
    float r2 = heap.d2[0];
    if (found < k && params.max_radius > 0.0f) r2 = params.max_radius * params.max_radius;
    if (!(r2 > 0.0f)) return out;
    const float r = sqrtf(r2);
    const float cone_k = params.cone_k < 1.0f ? 1.0f : params.cone_k;
    glm::vec3 flux(0.0f);
    if (params.cone_filter) {
        for (std::uint32_t i = 0; i < found; ++i)
            flux += cone_weight(sqrtf(heap.d2[i]), cone_k, r) * power_of(map, heap.index[i]);
    } else {
        for (std::uint32_t i = 0; i < found; ++i) flux += power_of(map, heap.index[i]);  // w = 1
    }
    const float norm = params.cone_filter ? cone_norm(cone_k) : 1.0f;
    const float area_share = params.plane_distance > 0.0f ? covered_share(map, heap, found, position, normal, r2) : 1.0f;
    out.radiance = lambert_brdf(albedo) * flux / (kPi * r2 * norm * area_share);
    out.radius = r;
    return out;
}

// `normal`: unit surface normal on the viewer's side; `albedo`: the diffuse reflectance.
//
// radius_hint > 0: a radius that probably holds k accepted photons, e.g. a neighbouring query's
// k-th distance plus the distance between the two points (exactly such a bound for the same
// filter and a sphere); the search starts there (search_from_hint). The same k nearest are
// found; only their order in the result may differ, and with it the last bits of the sum, and
// which of several photons at exactly the k-th distance is kept.
//
// memo (CPU only; may be null): the filter's decisions remembered from earlier searches
// (FilterMemo); not used with decoded vectors (map.unpacked), whose batched decisions are cheaper.
KDPM_HD inline RadianceEstimate estimate_radiance(const PhotonMapView& map, glm::vec3 position, glm::vec3 normal,
                                                  glm::vec3 albedo, const RadianceEstimateParams& params,
                                                  KnnHeap& heap, float radius_hint = 0.0f,
                                                  FilterMemo* memo = nullptr) {
    const SurfacePhotonFilter filter(map, normal, params.min_normal_cos, params.min_bounce, params.exclude_flags);
    if (params.fixed_radius) return estimate_radiance_in_radius(map, position, albedo, params, filter);
    const std::uint32_t k = clamp_gather_k(params.k);
    // One search per filter kind, along the sphere or the flattened disc.
    auto search_with = [&](const auto& accept, float limit) {
        return params.flatten > 0.0f
                   ? knn_search(map, position, k, limit, DiscMetric{normal, params.flatten}, accept, heap)
                   : knn_search(map, position, k, limit, EuclideanMetric{}, accept, heap);
    };
    std::uint32_t found = 0;
    if (params.plane_distance > 0.0f) {
        // The plane test on top of the surface filter; no memo (it remembers the surface filter's
        // decisions alone).
        const OnPlaneFilter<SurfacePhotonFilter> on_plane{filter, map.x, map.y, map.z, position, normal,
                                                          params.plane_distance};
        found = search_from_hint([&](float limit) { return search_with(on_plane, limit); }, k, radius_hint,
                                 params.max_radius);
    } else {
#if !defined(__CUDA_ARCH__)
        // With decoded vectors the filter decides 16 photons in a few SIMD steps (accepted16):
        // cheaper than looking up remembered decisions one photon at a time.
        if (map.unpacked) memo = nullptr;
        if (memo) memo->use_for(map, normal, params.min_normal_cos, params.min_bounce, params.exclude_flags);
#endif
        found = search_from_hint(
            [&](float limit) {
#if !defined(__CUDA_ARCH__)
                if (memo) return search_with(MemoizedFilter<SurfacePhotonFilter>{&filter, memo}, limit);
#endif
                return search_with(filter, limit);
            },
            k, radius_hint, params.max_radius);
    }
    return estimate_from_found(map, heap, found, k, position, normal, albedo, params);
}

// estimate_radiance started from the bound the hints give at `position` on the surface of
// `normal` (RadiusHints), which then remember this estimate's radius when it found all k photons.
KDPM_HD inline RadianceEstimate estimate_radiance_near(const PhotonMapView& map, glm::vec3 position, glm::vec3 normal,
                                                       glm::vec3 albedo, const RadianceEstimateParams& params,
                                                       KnnHeap& heap, RadiusHints& hints, FilterMemo* memo = nullptr) {
    const RadianceEstimate e =
        estimate_radiance(map, position, normal, albedo, params, heap, hints.hint(position, normal), memo);
    if (!params.fixed_radius && e.count == clamp_gather_k(params.k)) hints.remember(position, normal, e.radius);
    return e;
}

}  // namespace kdpm
