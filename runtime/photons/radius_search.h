#pragma once
// The fixed-radius photon search: calls visit(photon index, squared distance) for every photon
// with squared distance < radius^2 (no order), walking only subtrees whose split plane is closer.
#include <cassert>
#include <cstdint>

#include <glm/glm.hpp>

#include "formats/host_device.h"
#include "runtime/photons/photon_map_view.h"

namespace kdpm {

template <class Visit>
KDPM_HD void radius_search(const PhotonMapView& map, glm::vec3 q, float radius, const Visit& visit) {
    if (map.node_count == 0 || !(radius > 0.0f)) return;
    const float r2 = radius * radius;
    const float qc[3] = {q.x, q.y, q.z};
    // Bounded as in knn_search: the validator's depth limit means no push is ever dropped.
    std::uint32_t stack[kMaxPhotonTreeDepth + 1];
    std::uint32_t top = 0;
    std::uint32_t node = 0;
    for (;;) {
        KdNode n = map.nodes[node];
        while (!n.is_leaf()) {
            const float d = qc[n.axis()] - n.split();
            const std::uint32_t above = n.above_child();
            assert(top <= kMaxPhotonTreeDepth && "photon tree deeper than kMaxPhotonTreeDepth");
            if (d * d < r2 && top <= kMaxPhotonTreeDepth) stack[top++] = d < 0.0f ? above : node + 1;
            node = d < 0.0f ? node + 1 : above;
            n = map.nodes[node];
        }
        const std::uint32_t first = n.first(), end = first + n.count();
        for (std::uint32_t p = first; p < end; ++p) {
            const float dx = map.x[p] - q.x, dy = map.y[p] - q.y, dz = map.z[p] - q.z;
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < r2) visit(p, d2);
        }
        if (top == 0) return;
        node = stack[--top];
    }
}

}  // namespace kdpm
