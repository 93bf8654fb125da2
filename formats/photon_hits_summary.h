#pragma once
// The counts and bounds a PhotonHitsInfo states about its hits, computed in one place for the
// shooter (runtime) and the hit-file tools (builders).
#include <algorithm>
#include <cstdint>
#include <span>

#include "formats/photon_layout.h"

namespace kdpm {

// Sets stored_count, caustic_count and bounds (0 when there are no hits); other fields stay.
inline void summarize_photon_hits(std::span<const PhotonHit> hits, PhotonHitsInfo& info) {
    info.stored_count = static_cast<std::uint32_t>(hits.size());
    info.caustic_count = 0;
    for (int a = 0; a < 3; ++a) info.bounds_min[a] = info.bounds_max[a] = 0.0f;
    bool first = true;
    for (const auto& h : hits) {
        if (h.flags & kPhotonCaustic) ++info.caustic_count;
        for (int a = 0; a < 3; ++a) {
            info.bounds_min[a] = first ? h.position[a] : std::min(info.bounds_min[a], h.position[a]);
            info.bounds_max[a] = first ? h.position[a] : std::max(info.bounds_max[a], h.position[a]);
        }
        first = false;
    }
}

}  // namespace kdpm
