#pragma once
// A photon map as the gather kernels read it: the kd-tree nodes and the photons in leaf order
// as plain arrays (a mapped .kdp on the CPU, device copies on the GPU).
#include <cstdint>

#include "formats/kd_node.h"
#include "formats/photon_layout.h"

namespace kdpm {

struct PhotonMapView {
    const KdNode* nodes = nullptr;
    std::uint32_t node_count = 0;  // 0: an empty map (every search finds nothing)
    std::uint32_t photon_count = 0;
    const float* x = nullptr;
    const float* y = nullptr;
    const float* z = nullptr;
    const std::uint32_t* power = nullptr;                // RGBE (decode_rgbe)
    const PackedPhotonDirections* directions = nullptr;  // octahedral (decode_octahedral)
    const std::uint32_t* flags = nullptr;                // kPhotonCaustic, bounce
    // CPU only, may be null: decode_octahedral of each photon's direction and of its surface
    // normal, decoded once for many searches (unpack_directions), as 6 arrays of photon_count
    // floats (direction x, y, z, normal x, y, z: component c of photon p at
    // unpacked[c * photon_count + p]) that SIMD lanes load; null: decoded per use.
    const float* unpacked = nullptr;
    // CPU only, may be null: each photon's power as photon_power decodes it, 3 floats a photon
    // (unpack_powers); null: decoded per use.
    const float* unpacked_power = nullptr;
    // CPU only, may be null: per node, the boxes of its photons' decoded directions and normals
    // and what their flags share (bound_node_vectors, kVectorBoundFloats a node), for surface
    // filters that rule out whole subtrees; null: every subtree within the radius is walked.
    const float* vector_bounds = nullptr;
    std::uint64_t emitted_count = 0;                     // photon paths emitted by the shooter
};

}  // namespace kdpm
