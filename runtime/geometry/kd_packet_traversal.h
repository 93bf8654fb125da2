#pragma once
// Closest hits of a packet of coherent rays (camera rays of one tile) in one walk of the SAH
// geometry kd-tree (Wald, Slusallek, Benthin & Wagner 2001: "Interactive rendering with coherent
// ray tracing"). Each node is read once for the whole packet and its plane tested against four
// rays per SSE2 instruction, eight per AVX2 instruction or all sixteen per AVX-512 instruction,
// the widest the CPU has (chosen at run time); each leaf triangle is tested against as many rays
// at a time (kd_packet_walk.inc).
//
// The result is the single-ray walk's, bit for bit: every lane keeps the segment the single-ray
// walk would have at that node, enters every leaf with triangles that walk enters, in the same
// order, tests their triangles with the same arithmetic in the same order, and stops where that
// walk stops. That needs all rays to order every node's children alike, which a shared origin
// guarantees but at a plane through the origin itself, where the rays' direction signs decide:
// packets from several origins, and the rare packet that meets such a plane with mixed signs,
// take the single-ray walk. The same walk answers occlusion (shadow rays from one point).
// CPU only: on the GPU each thread walks its own ray.
#include <cstdint>

#include "formats/host_device.h"
#include "runtime/geometry/cpu_features.h"
#include "runtime/geometry/packet_box_test.h"
#include "runtime/geometry/scene_traversal.h"
#include "runtime/geometry/sse2_ops.h"

#if defined(__SSE2__) && defined(__x86_64__) && !defined(__CUDACC__)
#include <immintrin.h>
#define KDPM_PACKET_SIMD 1
#endif

namespace kdpm {

// Rays in one packet: a 4x4 pixel block.
inline constexpr std::uint32_t kPacketRays = 16;

struct RayPacket {
    // Structure of arrays, lane i = ray i; lanes at or past `count` are ignored.
    alignas(32) float origin[3][kPacketRays];
    alignas(32) float direction[3][kPacketRays];
    alignas(32) float tmin[kPacketRays];
    alignas(32) float tmax[kPacketRays];
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

// One origin: every node then orders its children alike for all rays (the near child is the
// origin's side), except where the origin lies on the node's plane and the single-ray walk's
// tie rule reads each ray's `direction <= 0`; the walk gives such packets back (walk_simd).
inline bool shares_origin(const RayPacket& p) {
    for (int a = 0; a < 3; ++a)
        for (std::uint32_t i = 1; i < p.count; ++i)
            if (p.origin[a][i] != p.origin[a][0]) return false;
    return true;
}

#if defined(KDPM_PACKET_SIMD)

using LaneMask = std::uint32_t;  // bit i: lane i
constexpr LaneMask kAllLanes = (1u << kPacketRays) - 1u;
static_assert(kPacketRays < 32);

// The operations kd_packet_walk.inc is written in. SSE2: four lanes (sse2_ops.h).
using kdpm::Sse2Ops;

namespace sse2 {
using S = Sse2Ops;
#include "runtime/geometry/kd_packet_walk.inc"
}  // namespace sse2

// AVX2: eight lanes, compiled for AVX2 in this region only and run only where the CPU has it
// (closest_hits checks once), so one binary runs on every x86-64.
KDPM_BEGIN_TARGET("avx2")
struct Avx2Ops {
    using V = __m256;
    using VI = __m256i;
    using M = __m256;
    static constexpr int kWidth = 8;
    static V load(const float* p) { return _mm256_loadu_ps(p); }
    static void store(float* p, V v) { _mm256_storeu_ps(p, v); }
    static void store_i(std::uint32_t* p, VI v) { _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v); }
    static V set1(float x) { return _mm256_set1_ps(x); }
    static VI set1_i(int x) { return _mm256_set1_epi32(x); }
    static V zero() { return _mm256_setzero_ps(); }
    static M not_(M m) { return _mm256_andnot_ps(m, _mm256_castsi256_ps(_mm256_set1_epi32(-1))); }
    static V add(V a, V b) { return _mm256_add_ps(a, b); }
    static V sub(V a, V b) { return _mm256_sub_ps(a, b); }
    static V mul(V a, V b) { return _mm256_mul_ps(a, b); }
    static V div(V a, V b) { return _mm256_div_ps(a, b); }
    static V lt(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
    static V le(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_LE_OQ); }
    static V gt(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_GT_OQ); }
    static V ge(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_GE_OQ); }
    static V nle(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_NLE_UQ); }
    static V neq(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_NEQ_UQ); }
    static V eq_i(VI a, VI b) { return _mm256_castsi256_ps(_mm256_cmpeq_epi32(a, b)); }
    static V and_(V a, V b) { return _mm256_and_ps(a, b); }
    static V or_(V a, V b) { return _mm256_or_ps(a, b); }
    static V andnot(V a, V b) { return _mm256_andnot_ps(a, b); }
    static int movemask(V v) { return _mm256_movemask_ps(v); }
    static V select(V mask, V a, V b) { return _mm256_blendv_ps(b, a, mask); }
    static VI select_i(V mask, VI a, VI b) {
        return _mm256_castps_si256(_mm256_blendv_ps(_mm256_castsi256_ps(b), _mm256_castsi256_ps(a), mask));
    }
    static V lanes_of(LaneMask bits) {
        const VI lane_bit = _mm256_set_epi32(128, 64, 32, 16, 8, 4, 2, 1);
        return eq_i(_mm256_and_si256(_mm256_set1_epi32(static_cast<int>(bits)), lane_bit), lane_bit);
    }
};

namespace avx2 {
using S = Avx2Ops;
#include "runtime/geometry/kd_packet_walk.inc"
}  // namespace avx2
KDPM_END_TARGET

// AVX-512: the whole packet in one vector, lane masks in mask registers. Its own region for the
// same reason as AVX2's. AVX-512 brings fused multiply-add, and GCC contracts a plain multiply
// feeding an add into one (rounding once where the scalar walk rounds twice) unless told
// -ffp-contract=off: the arithmetic is spelled with explicit round-to-nearest, which no compiler
// fuses, whatever the flags of the program that includes this header.
KDPM_BEGIN_TARGET("avx512f")
struct Avx512Ops {
    using V = __m512;
    using VI = __m512i;
    using M = __mmask16;
    static constexpr int kWidth = 16;
    static V load(const float* p) { return _mm512_loadu_ps(p); }
    static void store(float* p, V v) { _mm512_storeu_ps(p, v); }
    static void store_i(std::uint32_t* p, VI v) { _mm512_storeu_si512(p, v); }
    static V set1(float x) { return _mm512_set1_ps(x); }
    static VI set1_i(int x) { return _mm512_set1_epi32(x); }
    static V zero() { return _mm512_setzero_ps(); }
    static M not_(M m) { return static_cast<M>(~m); }
    // The zero-masking forms with every lane kept: GCC 12's plain _round_ forms warn of an
    // uninitialised source inside its own header.
    static constexpr int kNearest = _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC;
    static constexpr M kAll = 0xffff;
    static V add(V a, V b) { return _mm512_maskz_add_round_ps(kAll, a, b, kNearest); }
    static V sub(V a, V b) { return _mm512_maskz_sub_round_ps(kAll, a, b, kNearest); }
    static V mul(V a, V b) { return _mm512_maskz_mul_round_ps(kAll, a, b, kNearest); }
    static V div(V a, V b) { return _mm512_maskz_div_round_ps(kAll, a, b, kNearest); }
    static M lt(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_LT_OQ); }
    static M le(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_LE_OQ); }
    static M gt(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }
    static M ge(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ); }
    static M nle(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_NLE_UQ); }
    static M neq(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_NEQ_UQ); }
    static M eq_i(VI a, VI b) { return _mm512_cmpeq_epi32_mask(a, b); }
    static M and_(M a, M b) { return static_cast<M>(a & b); }
    static M or_(M a, M b) { return static_cast<M>(a | b); }
    static M andnot(M a, M b) { return static_cast<M>(~a & b); }
    static int movemask(M m) { return m; }
    static V select(M mask, V a, V b) { return _mm512_mask_blend_ps(mask, b, a); }
    static VI select_i(M mask, VI a, VI b) { return _mm512_mask_blend_epi32(mask, b, a); }
    static M lanes_of(LaneMask bits) { return static_cast<M>(bits); }
};

namespace avx512 {
using S = Avx512Ops;
#include "runtime/geometry/kd_packet_walk.inc"
}  // namespace avx512
KDPM_END_TARGET

using kdpm::cpu_has_avx2;  // runtime/geometry/cpu_features.h
using kdpm::cpu_has_avx512;

#endif  // KDPM_PACKET_SIMD

}  // namespace packet_detail

// Which walk: the widest the CPU has by default; tests name each.
enum class PacketIsa { best, sse2, avx2, avx512 };

namespace packet_detail {

// Runs walk_simd<kAnyHit> for the ISA; false when the packet must go ray by ray.
template <bool kAnyHit>
inline bool walk_packet(const GeometryView& g, const RayPacket& p, Hit* out, bool* occluded, PacketIsa simd) {
#if defined(KDPM_PACKET_SIMD)
    if (p.count < 2 || !shares_origin(p)) return false;
    if (simd == PacketIsa::best)
        simd = cpu_has_avx512() ? PacketIsa::avx512 : cpu_has_avx2() ? PacketIsa::avx2 : PacketIsa::sse2;
    auto walk = [&](const RayPacket& packet) {
        if (simd == PacketIsa::avx512) return avx512::walk_simd<kAnyHit>(g, packet, out, occluded);
        if (simd == PacketIsa::avx2) return avx2::walk_simd<kAnyHit>(g, packet, out, occluded);
        return sse2::walk_simd<kAnyHit>(g, packet, out, occluded);
    };
    // Lanes past count copy lane 0, so that no SIMD lane holds garbage (their results are dropped).
    if (p.count < kPacketRays) {
        RayPacket full = p;
        for (std::uint32_t i = p.count; i < kPacketRays; ++i) full.set(i, p.ray(0));
        return walk(full);
    }
    return walk(p);
#else
    (void)g, (void)p, (void)out, (void)occluded, (void)simd;
    return false;
#endif
}

// A scene of instances, the packet together: it walks the instance BVH entering a node when any
// lane still searching enters it (each lane within its nearest hit so far), nearer child first
// along the first such lane; at each instance the lanes that enter its box go into the object's
// frame by its one map, so a shared origin stays shared, and walk the object's tree as a packet.
// Each lane's hit is the one the single-ray walk of the same instances finds (ties aside, the
// object's binary walk being the packet's reference, as in a flat scene).
template <bool kAnyHit>
inline void walk_instances_packet(const GeometryView& g, const RayPacket& p, Hit* out, bool* occluded, PacketIsa simd) {
    const std::uint32_t n = p.count;
    std::uint32_t searching = 0;  // bit i: lane i may still find a (closer) hit
    for (std::uint32_t i = 0; i < n; ++i) {
        if constexpr (kAnyHit) occluded[i] = false;
        else out[i] = miss(p.tmax[i]);
        searching |= 1u << i;
    }
    if (g.instance_node_count == 0 || n == 0) return;
    PacketBoxTest boxes(p.origin, p.direction, p.tmin, p.tmax, n);
    const bool shared = shares_origin(p);
    std::uint32_t stack[kMaxInstanceBvhDepth + 1];
    std::uint32_t top = 0;
    stack[top++] = 0;
    while (top > 0 && searching != 0) {
        const std::uint32_t index = stack[--top];
        const InstanceNode& node = g.instance_nodes[index];
        const std::uint32_t lanes = boxes.entering(node.lo, node.hi) & searching;
        if (lanes == 0) continue;
        if (node.count == 0) {
            // Far child first on the stack; "near" by the box centres along the first lane's ray.
            const std::uint32_t lead = static_cast<std::uint32_t>(__builtin_ctz(lanes));
            const glm::vec3 o(p.origin[0][lead], p.origin[1][lead], p.origin[2][lead]);
            const glm::vec3 d(p.direction[0][lead], p.direction[1][lead], p.direction[2][lead]);
            const InstanceNode& a = g.instance_nodes[node.first];
            const InstanceNode& b = g.instance_nodes[node.first + 1];
            auto along = [&](const InstanceNode& c) {
                float s = 0.0f;
                for (int k = 0; k < 3; ++k) s += (0.5f * (c.lo[k] + c.hi[k]) - o[k]) * d[k];
                return s;
            };
            const float da = along(a), db = along(b);
            stack[top++] = da <= db ? node.first + 1 : node.first;
            stack[top++] = da <= db ? node.first : node.first + 1;
            continue;
        }
        const InstancePlacement& placement = g.instances[node.first];
        const GeometryView& object = g.objects[placement.object];
        RayPacket local;
        local.count = n;
        const glm::vec3 o0 = apply_point(placement.object_from_world, glm::vec3(p.origin[0][0], p.origin[1][0], p.origin[2][0]));
        for (std::uint32_t i = 0; i < n; ++i) {
            const Ray world = p.ray(i);
            // A shared origin maps once (the same arithmetic: the same point in every lane).
            const glm::vec3 o = shared ? o0 : apply_point(placement.object_from_world, world.origin);
            const float t1 = lanes >> i & 1u ? boxes.tmax[i] : world.tmin;  // lanes outside the box search nothing
            local.set(i, Ray{o, world.tmin, apply_vector(placement.object_from_world, world.direction), t1});
        }
        Hit hits[kPacketRays];
        bool blocked[kPacketRays];
        if (!walk_packet<kAnyHit>(object, local, hits, blocked, simd))
            for (std::uint32_t i = 0; i < n; ++i)
                if (lanes >> i & 1u) {
                    if constexpr (kAnyHit) blocked[i] = occluded_kd(object, local.ray(i));
                    else hits[i] = closest_hit_kd(object, local.ray(i));
                }
        for (std::uint32_t i = 0; i < n; ++i) {
            if (!(lanes >> i & 1u)) continue;
            if constexpr (kAnyHit) {
                if (blocked[i]) {
                    occluded[i] = true;
                    searching &= ~(1u << i);
                }
            } else if (hits[i].found() && hits[i].t < boxes.tmax[i]) {
                out[i] = hits[i];
                out[i].instance = node.first;
                boxes.tmax[i] = hits[i].t;
            }
        }
    }
}

}  // namespace packet_detail

// out[i] = closest_hit_kd(g, p.ray(i)) for i < p.count, bit for bit (the binary walk's hits); in a
// scene of instances, each instance's object walked so.
inline void closest_hits(const GeometryView& g, const RayPacket& p, Hit* out, PacketIsa simd = PacketIsa::best) {
    if (g.instance_count != 0) return packet_detail::walk_instances_packet<false>(g, p, out, nullptr, simd);
    if (packet_detail::walk_packet<false>(g, p, out, nullptr, simd)) return;
    for (std::uint32_t i = 0; i < p.count; ++i) out[i] = closest_hit_kd(g, p.ray(i));
}

// out[i] = occluded_kd(g, p.ray(i)) for i < p.count: shadow rays from one point.
inline void occluded_rays(const GeometryView& g, const RayPacket& p, bool* out, PacketIsa simd = PacketIsa::best) {
    if (g.instance_count != 0) return packet_detail::walk_instances_packet<true>(g, p, nullptr, out, simd);
    if (packet_detail::walk_packet<true>(g, p, nullptr, out, simd)) return;
    for (std::uint32_t i = 0; i < p.count; ++i) out[i] = occluded_kd(g, p.ray(i));
}

}  // namespace kdpm
