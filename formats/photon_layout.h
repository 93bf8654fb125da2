#pragma once
// Records of the photon files: photon hits (.kdph, written by kdpm-shoot-photons) and the photon
// kd-tree (.kdp, written by kdpm-build-photons, mapped in place by the runtime), plus the compact
// encodings the tree uses for power (shared-exponent RGBE) and directions (octahedral 16-bit
// pairs). Plain floats (no GLM) so the layout is exactly what SPEC.md says; the codecs are
// KDPM_HD so builder, CPU and GPU decode the same bits.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "formats/host_device.h"
#include "formats/kd_node.h"

namespace kdpm {

// ---- flags of a photon (PhotonHit::flags and the tree's flags array share this encoding) ----
inline constexpr std::uint32_t kPhotonCaustic = 1u;          // reached a diffuse surface via specular bounces only
inline constexpr std::uint32_t kPhotonBounceShift = 8;       // bits 8-15: number of bounces before this hit
inline constexpr std::uint32_t kPhotonBounceMask = 0xffu << kPhotonBounceShift;
inline constexpr std::uint32_t kPhotonKnownFlags = kPhotonCaustic | kPhotonBounceMask;

KDPM_HD inline std::uint32_t photon_bounce(std::uint32_t flags) { return (flags & kPhotonBounceMask) >> kPhotonBounceShift; }
KDPM_HD inline std::uint32_t make_photon_flags(std::uint32_t bounce, bool caustic) {
    return ((bounce << kPhotonBounceShift) & kPhotonBounceMask) | (caustic ? kPhotonCaustic : 0u);
}

// ---- photon hits (.kdph) ----

// Section hits.info, one record.
struct PhotonHitsInfo {
    std::uint64_t emitted_count;   // photon paths emitted from the lights
    std::uint32_t stored_count;    // == hits.photons count
    std::uint32_t caustic_count;   // stored photons with kPhotonCaustic
    std::uint32_t max_bounces;     // bounce limit of the shooting (every hit has bounce <= this)
    std::uint32_t reserved0;
    float bounds_min[3];           // of the stored positions (0 when none)
    float bounds_max[3];
    float emitted_power[3];        // total RGB power of the lights (W); each path carries emitted_power / emitted_count
    std::uint32_t reserved1;
};
static_assert(sizeof(PhotonHitsInfo) == 64);

// Section hits.photons: one record per stored hit, in photon-path order then bounce order.
struct PhotonHit {
    float position[3];
    std::uint32_t flags;           // kPhotonCaustic | bounce << kPhotonBounceShift
    float power[3];                // RGB flux carried (W)
    std::uint32_t path;            // index of the emitted photon path
    float direction[3];            // unit direction of travel (points into the surface)
    std::uint32_t reserved0;
    float normal[3];               // unit geometric normal on the side the photon arrived from
    std::uint32_t reserved1;
};
static_assert(sizeof(PhotonHit) == 64);

// ---- photon kd-tree (.kdp) ----

enum class PhotonTreeBuilder : std::uint32_t { vvh = 0, balanced = 1 };

// Section photon_tree.info (and its caustic twin), one record.
struct PhotonTreeInfo {
    float bounds_min[3];           // the root cell: bounds of the photons (0 when none)
    std::uint32_t photon_count;
    float bounds_max[3];
    std::uint32_t node_count;
    std::uint32_t leaf_count;
    std::uint32_t max_depth;       // root depth 0; at most kMaxPhotonTreeDepth
    std::uint32_t max_leaf_size;   // largest leaf
    std::uint32_t builder;         // PhotonTreeBuilder
    float query_radius;            // expected query radius the VVH cost used (0 for balanced)
    std::uint32_t max_bounces;     // from the photon hits
    std::uint64_t emitted_count;   // from the photon hits: photon paths emitted
};
static_assert(sizeof(PhotonTreeInfo) == 64);

// Traversal stacks are fixed arrays of this depth; builders never go deeper and validators refuse deeper trees.
inline constexpr std::uint32_t kMaxPhotonTreeDepth = 60;

// Incoming direction and surface normal, each an octahedral 16+16-bit unit vector.
struct PackedPhotonDirections {
    std::uint32_t direction;
    std::uint32_t normal;
};
static_assert(sizeof(PackedPhotonDirections) == 8);

// The photon maps of one .kdp; each map's sections are base + PhotonTreeField. The irradiance
// map (format 1.1, optional) holds a subset of the global map's photons with the irradiance
// precomputed at each (Christensen 1999), for final gathering's one-lookup gather hits.
enum class PhotonMapKind : std::uint32_t { global = 0, caustic = 1, irradiance = 2 };
enum PhotonTreeField : std::uint32_t {
    ptree_field_info = 0,        // PhotonTreeInfo
    ptree_field_nodes = 1,       // KdNode[]
    ptree_field_x = 2,           // f32[] positions in leaf order
    ptree_field_y = 3,
    ptree_field_z = 4,
    ptree_field_power = 5,       // u32[] RGBE power
    ptree_field_directions = 6,  // PackedPhotonDirections[]
    ptree_field_flags = 7,       // u32[] photon flags
    // Irradiance map only:
    ptree_field_irradiance = 8,  // PrecomputedIrradiance[], in the map's leaf order
    ptree_field_source = 9,      // u32[]: the photon's index (leaf order) in the global map
};

// The irradiance (W / m^2, RGB) at a photon, from the global map's k-nearest density estimate
// over every photon, at the photon's position and stored normal.
struct PrecomputedIrradiance {
    float rgb[3];
};
static_assert(sizeof(PrecomputedIrradiance) == 12);
inline constexpr std::uint32_t photon_tree_section(PhotonMapKind map, PhotonTreeField field) {
    return 0x300u + 0x10u * static_cast<std::uint32_t>(map) + static_cast<std::uint32_t>(field);
}

// ---- codecs ----

// Shared-exponent RGB (Ward's RGBE): 8-bit mantissas, bits 24-31 the biased exponent.
// Relative error below 1/256 of the largest channel; zero and negatives encode as 0, values
// of 2^127 and above as the largest encodable one.
inline std::uint32_t encode_rgbe(float r, float g, float b) {
    float m = r > g ? r : g;
    m = m > b ? m : b;
    if (!(m > 1e-32f)) return 0;
    int e = 128;
    if (std::isfinite(m)) std::frexp(m, &e);  // m = f * 2^e, f in [0.5, 1)
    // The biased exponent has 8 bits: at 2^127 and above (and for infinity) saturate at the
    // largest encodable value instead of wrapping to 0, which would read as black.
    if (e > 127) e = 127;
    float scale = std::ldexp(256.0f, -e);    // largest channel maps into [128, 256)
    auto q = [&](float c) -> std::uint32_t {
        float v = c > 0.0f ? c * scale + 0.5f : 0.0f;
        return v >= 255.0f ? 255u : static_cast<std::uint32_t>(v);
    };
    return q(r) | (q(g) << 8) | (q(b) << 16) | (static_cast<std::uint32_t>(e + 128) << 24);
}
// 2^(e - 136), the scale of a biased exponent e >= 1: built from its bits where it is a normal
// float (exactly ldexpf's result there), so that hot loops decode without a libm call.
KDPM_HD KDPM_INLINE float rgbe_scale(std::uint32_t e) {
    if (e < 10) return ldexpf(1.0f, static_cast<int>(e) - 128 - 8);  // below the normal floats
    const std::uint32_t bits = (e - 9) << 23;                          // biased exponent (e - 136) + 127
    float scale;
    std::memcpy(&scale, &bits, sizeof scale);
    return scale;
}
KDPM_HD inline void decode_rgbe(std::uint32_t v, float out[3]) {
    std::uint32_t e = v >> 24;
    if (e == 0) {
        out[0] = out[1] = out[2] = 0.0f;
        return;
    }
    const float scale = rgbe_scale(e);
    out[0] = static_cast<float>(v & 0xffu) * scale;
    out[1] = static_cast<float>((v >> 8) & 0xffu) * scale;
    out[2] = static_cast<float>((v >> 16) & 0xffu) * scale;
}

// Octahedral unit vector: x in bits 0-15, y in bits 16-31, each a snorm16.
inline std::uint32_t encode_octahedral(float x, float y, float z) {
    float s = std::fabs(x) + std::fabs(y) + std::fabs(z);
    if (!(s > 0.0f)) return encode_octahedral(0.0f, 0.0f, 1.0f);
    float u = x / s, v = y / s;
    if (z < 0.0f) {
        float fu = (1.0f - std::fabs(v)) * (u >= 0.0f ? 1.0f : -1.0f);
        float fv = (1.0f - std::fabs(u)) * (v >= 0.0f ? 1.0f : -1.0f);
        u = fu;
        v = fv;
    }
    auto q = [](float c) -> std::uint32_t {
        c = c < -1.0f ? -1.0f : (c > 1.0f ? 1.0f : c);
        auto i = static_cast<std::int32_t>(std::lround(c * 32767.0f));
        return static_cast<std::uint32_t>(static_cast<std::uint16_t>(static_cast<std::int16_t>(i)));
    };
    return q(u) | (q(v) << 16);
}
// The octahedron's point (u, v, 1 - |u| - |v|), its lower half folded back: the decoded vector
// before normalisation (length in [0.57, 1]).
KDPM_HD KDPM_INLINE void octahedral_unfold(float u, float v, float out[3]) {
    const float z = 1.0f - fabsf(u) - fabsf(v);
    if (z < 0.0f) {
        const float fu = (1.0f - fabsf(v)) * (u >= 0.0f ? 1.0f : -1.0f);
        v = (1.0f - fabsf(u)) * (v >= 0.0f ? 1.0f : -1.0f);
        u = fu;
    }
    out[0] = u;
    out[1] = v;
    out[2] = z;
}
KDPM_HD inline void decode_octahedral(std::uint32_t packed, float out[3]) {
    auto c = [](std::uint32_t bits) {
        float f = static_cast<float>(static_cast<std::int16_t>(static_cast<std::uint16_t>(bits))) / 32767.0f;
        return f < -1.0f ? -1.0f : f;
    };
    float w[3];
    octahedral_unfold(c(packed & 0xffffu), c(packed >> 16), w);
    float inv = 1.0f / sqrtf(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    out[0] = w[0] * inv;
    out[1] = w[1] * inv;
    out[2] = w[2] * inv;
}

}  // namespace kdpm
