#pragma once
// Closest hits of a packet of coherent rays (camera rays of one tile) in one walk of the SAH
// geometry kd-tree (Wald, Slusallek, Benthin & Wagner 2001: "Interactive rendering with coherent
// ray tracing"). Each node is read once for the whole packet and its plane tested against four
// rays per SSE2 instruction; each leaf triangle is tested against four rays at a time.
//
// The result is the single-ray walk's, bit for bit: every lane keeps the segment the single-ray
// walk would have at that node, enters exactly the leaves that walk enters, in the same order,
// tests their triangles with the same arithmetic in the same order, and stops where that walk
// stops. That needs all rays to order every node's children alike, which a shared origin and
// shared direction signs guarantee; other packets (a tile straddling an axis of the view) take
// the single-ray walk. CPU only: on the GPU each thread walks its own ray.
#include <cstdint>

#include "formats/host_device.h"
#include "runtime/geometry/kd_traversal.h"

#if defined(__SSE2__) && !defined(__CUDACC__)
#include <emmintrin.h>
#define KDPM_PACKET_SSE2 1
#endif

namespace kdpm {

// Rays in one packet: a 4x4 pixel block.
inline constexpr std::uint32_t kPacketRays = 16;

struct RayPacket {
    // Structure of arrays, lane i = ray i; lanes at or past `count` are ignored.
    alignas(16) float origin[3][kPacketRays];
    alignas(16) float direction[3][kPacketRays];
    alignas(16) float tmin[kPacketRays];
    alignas(16) float tmax[kPacketRays];
    std::uint32_t count = 0;

    void set(std::uint32_t lane, const Ray& r) {
        for (int a = 0; a < 3; ++a) {
            origin[a][lane] = r.origin[a];
            direction[a][lane] = r.direction[a];
        }
        tmin[lane] = r.tmin;
        tmax[lane] = r.tmax;
    }
    Ray ray(std::uint32_t lane) const {
        return Ray{glm::vec3(origin[0][lane], origin[1][lane], origin[2][lane]), tmin[lane],
                   glm::vec3(direction[0][lane], direction[1][lane], direction[2][lane]), tmax[lane]};
    }
};

namespace packet_detail {

// True when every node orders its children alike for all rays: one origin, and per axis one
// sign class of the direction (the single-ray walk's tie rule reads `direction <= 0`).
inline bool walks_as_one(const RayPacket& p) {
    for (int a = 0; a < 3; ++a) {
        const bool not_up = p.direction[a][0] <= 0.0f;
        for (std::uint32_t i = 0; i < p.count; ++i)
            if (p.origin[a][i] != p.origin[a][0] || (p.direction[a][i] <= 0.0f) != not_up) return false;
    }
    return true;
}

#if defined(KDPM_PACKET_SSE2)

constexpr int kGroups = kPacketRays / 4;
using LaneMask = std::uint32_t;  // bit i: lane i

// The four-lane SSE mask of bits 4g..4g+3 of m.
inline __m128 group_mask(LaneMask m, int g) {
    const std::uint32_t b = m >> (4 * g);
    return _mm_castsi128_ps(_mm_set_epi32(-static_cast<int>((b >> 3) & 1u), -static_cast<int>((b >> 2) & 1u),
                                          -static_cast<int>((b >> 1) & 1u), -static_cast<int>(b & 1u)));
}
inline LaneMask bits_of(__m128 m, int g) { return static_cast<LaneMask>(_mm_movemask_ps(m)) << (4 * g); }
inline __m128 select(__m128 mask, __m128 a, __m128 b) {
    return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

struct PacketEntry {
    std::uint32_t node;
    LaneMask active;
    // Lanes the single-ray walk pushed here (they crossed the plane); the other active lanes
    // went to this child directly there and are deferred only because neighbours went near.
    LaneMask pushed;
    __m128 tmin[kGroups], tmax[kGroups];
};

struct PacketHits {
    __m128 t[kGroups], u[kGroups], v[kGroups];
    __m128i triangle[kGroups];
};

// intersect_triangle() for four rays: the same operations in the same order, so each lane's
// t, u, v are the scalar function's bits. Lanes outside `lanes` are left as they are.
inline void intersect_four(const TriangleRecord& tri, std::uint32_t index, const __m128 (&o)[3], const __m128 (&d)[3],
                           __m128 tmin, __m128 lanes, __m128& best_t, __m128& best_u, __m128& best_v,
                           __m128i& best_tri) {
    const __m128 e1x = _mm_set1_ps(tri.e1[0]), e1y = _mm_set1_ps(tri.e1[1]), e1z = _mm_set1_ps(tri.e1[2]);
    const __m128 e2x = _mm_set1_ps(tri.e2[0]), e2y = _mm_set1_ps(tri.e2[1]), e2z = _mm_set1_ps(tri.e2[2]);
    // p = cross(d, e2), glm's operand order
    const __m128 px = _mm_sub_ps(_mm_mul_ps(d[1], e2z), _mm_mul_ps(e2y, d[2]));
    const __m128 py = _mm_sub_ps(_mm_mul_ps(d[2], e2x), _mm_mul_ps(e2z, d[0]));
    const __m128 pz = _mm_sub_ps(_mm_mul_ps(d[0], e2y), _mm_mul_ps(e2x, d[1]));
    const __m128 det = _mm_add_ps(_mm_add_ps(_mm_mul_ps(e1x, px), _mm_mul_ps(e1y, py)), _mm_mul_ps(e1z, pz));
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
    __m128 ok = _mm_and_ps(lanes, _mm_cmpneq_ps(det, zero));
    if (_mm_movemask_ps(ok) == 0) return;
    const __m128 inv_det = _mm_div_ps(one, det);
    const __m128 sx = _mm_sub_ps(o[0], _mm_set1_ps(tri.v0[0]));
    const __m128 sy = _mm_sub_ps(o[1], _mm_set1_ps(tri.v0[1]));
    const __m128 sz = _mm_sub_ps(o[2], _mm_set1_ps(tri.v0[2]));
    const __m128 uu =
        _mm_mul_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(sx, px), _mm_mul_ps(sy, py)), _mm_mul_ps(sz, pz)), inv_det);
    ok = _mm_and_ps(ok, _mm_and_ps(_mm_cmpge_ps(uu, zero), _mm_cmple_ps(uu, one)));
    if (_mm_movemask_ps(ok) == 0) return;
    // q = cross(s, e1)
    const __m128 qx = _mm_sub_ps(_mm_mul_ps(sy, e1z), _mm_mul_ps(e1y, sz));
    const __m128 qy = _mm_sub_ps(_mm_mul_ps(sz, e1x), _mm_mul_ps(e1z, sx));
    const __m128 qz = _mm_sub_ps(_mm_mul_ps(sx, e1y), _mm_mul_ps(e1x, sy));
    const __m128 vv =
        _mm_mul_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(d[0], qx), _mm_mul_ps(d[1], qy)), _mm_mul_ps(d[2], qz)), inv_det);
    ok = _mm_and_ps(ok, _mm_and_ps(_mm_cmpge_ps(vv, zero), _mm_cmple_ps(_mm_add_ps(uu, vv), one)));
    const __m128 tt =
        _mm_mul_ps(_mm_add_ps(_mm_add_ps(_mm_mul_ps(e2x, qx), _mm_mul_ps(e2y, qy)), _mm_mul_ps(e2z, qz)), inv_det);
    ok = _mm_and_ps(ok, _mm_and_ps(_mm_cmpgt_ps(tt, tmin), _mm_cmplt_ps(tt, best_t)));
    if (_mm_movemask_ps(ok) == 0) return;
    best_t = select(ok, tt, best_t);
    best_u = select(ok, uu, best_u);
    best_v = select(ok, vv, best_v);
    const __m128i oki = _mm_castps_si128(ok);
    best_tri = _mm_or_si128(_mm_and_si128(oki, _mm_set1_epi32(static_cast<int>(index))),
                            _mm_andnot_si128(oki, best_tri));
}

// The single-ray walk of kd_detail::walk with ClosestVisitor, for all lanes at once.
inline void closest_hits_sse(const GeometryView& g, const RayPacket& p, Hit* out) {
    __m128 org[3][kGroups], inv[3][kGroups], ray_tmin[kGroups];
    __m128 tmin[kGroups], tmax[kGroups];
    PacketHits h;
    LaneMask active = 0;
    for (int q = 0; q < kGroups; ++q) {
        for (int a = 0; a < 3; ++a) {
            org[a][q] = _mm_load_ps(&p.origin[a][4 * q]);
            inv[a][q] = _mm_div_ps(_mm_set1_ps(1.0f), _mm_load_ps(&p.direction[a][4 * q]));
        }
        ray_tmin[q] = _mm_load_ps(&p.tmin[4 * q]);
        h.t[q] = _mm_load_ps(&p.tmax[4 * q]);
        h.u[q] = h.v[q] = _mm_setzero_ps();
        h.triangle[q] = _mm_set1_epi32(static_cast<int>(kNoHit));
    }
    // Per lane: the scalar bounds clip (kd_detail::clip_to_bounds), so the same starting segment.
    alignas(16) float t0[kPacketRays], t1[kPacketRays];
    for (std::uint32_t i = 0; i < kPacketRays; ++i) {
        t0[i] = p.tmin[i];
        t1[i] = p.tmax[i];
        if (i >= p.count) continue;
        const glm::vec3 o(p.origin[0][i], p.origin[1][i], p.origin[2][i]);
        const glm::vec3 inv_dir(1.0f / p.direction[0][i], 1.0f / p.direction[1][i], 1.0f / p.direction[2][i]);
        if (kd_detail::clip_to_bounds(g.info, o, inv_dir, t0[i], t1[i])) active |= 1u << i;
    }
    for (int q = 0; q < kGroups; ++q) {
        tmin[q] = _mm_load_ps(&t0[4 * q]);
        tmax[q] = _mm_load_ps(&t1[4 * q]);
    }
    LaneMask done = ~active;  // lanes whose walk has stopped (or never started)

    if (g.node_count != 0 && active != 0) {
        const bool dir_not_up[3] = {p.direction[0][0] <= 0.0f, p.direction[1][0] <= 0.0f, p.direction[2][0] <= 0.0f};
        const float origin0[3] = {p.origin[0][0], p.origin[1][0], p.origin[2][0]};
        PacketEntry stack[kMaxKdDepth];
        std::uint32_t sp = 0;
        std::uint32_t node = 0;
        const __m128 zero = _mm_setzero_ps();
        for (;;) {
            KdNode n = g.nodes[node];
            while (!n.is_leaf()) {
                const int axis = n.axis();
                const float split = n.split();
                const __m128 split4 = _mm_set1_ps(split);
                // One origin: the child order is every lane's single-ray order.
                const float o = origin0[axis];
                const bool below_first = o < split || (o == split && dir_not_up[axis]);
                const std::uint32_t below = node + 1, above = n.above_child();
                const std::uint32_t first = below_first ? below : above;
                const std::uint32_t second = below_first ? above : below;
                __m128 tplane[kGroups], cross[kGroups];
                LaneMask near_lanes = 0, far_lanes = 0, cross_lanes = 0;
                for (int q = 0; q < kGroups; ++q) {
                    tplane[q] = _mm_mul_ps(_mm_sub_ps(split4, org[axis][q]), inv[axis][q]);
                    // near only: !(tplane <= tmax) || tplane <= 0; far only: else tplane < tmin
                    const __m128 near_only = _mm_or_ps(_mm_cmpnle_ps(tplane[q], tmax[q]), _mm_cmple_ps(tplane[q], zero));
                    const __m128 far_only = _mm_andnot_ps(near_only, _mm_cmplt_ps(tplane[q], tmin[q]));
                    cross[q] = _mm_andnot_ps(_mm_or_ps(near_only, far_only), _mm_castsi128_ps(_mm_set1_epi32(-1)));
                    near_lanes |= bits_of(_mm_or_ps(near_only, cross[q]), q);
                    far_lanes |= bits_of(_mm_or_ps(far_only, cross[q]), q);
                    cross_lanes |= bits_of(cross[q], q);
                }
                near_lanes &= active;
                far_lanes &= active;
                if (far_lanes == 0) {
                    node = first;
                } else if (near_lanes == 0) {
                    node = second;
                } else {
                    // Crossing lanes: near [tmin, tplane], far [tplane, tmax]; one-sided lanes keep
                    // their segment on their side.
                    assert(sp < kMaxKdDepth && "kd-tree deeper than kMaxKdTreeDepth");
                    if (sp < kMaxKdDepth) {
                        PacketEntry& e = stack[sp++];
                        e.node = second;
                        e.active = far_lanes;
                        e.pushed = cross_lanes & active;
                        for (int q = 0; q < kGroups; ++q) {
                            e.tmin[q] = select(cross[q], tplane[q], tmin[q]);
                            e.tmax[q] = tmax[q];
                        }
                    }
                    for (int q = 0; q < kGroups; ++q) tmax[q] = select(cross[q], tplane[q], tmax[q]);
                    node = first;
                    active = near_lanes;
                }
                if (far_lanes != 0 && near_lanes == 0) active = far_lanes;
                n = g.nodes[node];
            }
            // Leaf: its triangles against the live lanes, then stop the lanes whose hit lies
            // within their segment of this leaf.
            const LaneMask live = active & ~done;
            if (live != 0) {
                const std::uint32_t first = n.first(), count = n.count();
                for (int q = 0; q < kGroups; ++q) {
                    if (((live >> (4 * q)) & 0xfu) == 0) continue;
                    const __m128 lanes = group_mask(live, q);
                    const __m128 o[3] = {org[0][q], org[1][q], org[2][q]};
                    const __m128 d[3] = {_mm_load_ps(&p.direction[0][4 * q]), _mm_load_ps(&p.direction[1][4 * q]),
                                         _mm_load_ps(&p.direction[2][4 * q])};
                    for (std::uint32_t i = 0; i < count; ++i) {
                        const std::uint32_t tri = g.leaf_indices[first + i];
                        intersect_four(g.triangles[tri], tri, o, d, ray_tmin[q], lanes, h.t[q], h.u[q], h.v[q],
                                       h.triangle[q]);
                    }
                    const __m128 found = _mm_castsi128_ps(
                        _mm_xor_si128(_mm_cmpeq_epi32(h.triangle[q], _mm_set1_epi32(static_cast<int>(kNoHit))),
                                      _mm_set1_epi32(-1)));
                    done |= bits_of(_mm_and_ps(lanes, _mm_and_ps(found, _mm_cmple_ps(h.t[q], tmax[q]))), q);
                }
            }
            // Pop the next entry some lane still needs; a lane whose pushed entry starts beyond
            // its best hit is finished, as the single-ray walk returns there.
            bool resumed = false;
            while (sp > 0 && (~done & ((1u << kPacketRays) - 1u)) != 0) {
                const PacketEntry& e = stack[--sp];
                LaneMask lanes = e.active & ~done;
                const LaneMask check = e.pushed & lanes;
                for (int q = 0; q < kGroups && check != 0; ++q) {
                    if (((check >> (4 * q)) & 0xfu) == 0) continue;
                    const LaneMask beyond = bits_of(_mm_cmpgt_ps(e.tmin[q], h.t[q]), q) & check;
                    done |= beyond;
                    lanes &= ~beyond;
                }
                if (lanes == 0) continue;
                node = e.node;
                active = lanes;
                for (int q = 0; q < kGroups; ++q) {
                    tmin[q] = e.tmin[q];
                    tmax[q] = e.tmax[q];
                }
                resumed = true;
                break;
            }
            if (!resumed) break;
        }
    }
    alignas(16) float t[kPacketRays], u[kPacketRays], v[kPacketRays];
    alignas(16) std::uint32_t tri[kPacketRays];
    for (int q = 0; q < kGroups; ++q) {
        _mm_store_ps(&t[4 * q], h.t[q]);
        _mm_store_ps(&u[4 * q], h.u[q]);
        _mm_store_ps(&v[4 * q], h.v[q]);
        _mm_store_si128(reinterpret_cast<__m128i*>(&tri[4 * q]), h.triangle[q]);
    }
    for (std::uint32_t i = 0; i < p.count; ++i) out[i] = Hit{t[i], tri[i], u[i], v[i]};
}

#endif  // KDPM_PACKET_SSE2

}  // namespace packet_detail

// out[i] = closest_hit(g, p.ray(i)) for i < p.count, bit for bit.
inline void closest_hits(const GeometryView& g, const RayPacket& p, Hit* out) {
#if defined(KDPM_PACKET_SSE2)
    if (p.count > 1 && packet_detail::walks_as_one(p)) {
        // Lanes past count copy lane 0, so that the SSE groups hold no garbage (their results are dropped).
        if (p.count < kPacketRays) {
            RayPacket full = p;
            for (std::uint32_t i = p.count; i < kPacketRays; ++i) full.set(i, p.ray(0));
            packet_detail::closest_hits_sse(g, full, out);
            return;
        }
        packet_detail::closest_hits_sse(g, p, out);
        return;
    }
#endif
    for (std::uint32_t i = 0; i < p.count; ++i) out[i] = closest_hit(g, p.ray(i));
}

}  // namespace kdpm
