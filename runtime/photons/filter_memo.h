#pragma once
// Surface filter work remembered across k-nearest searches (the CPU gather's tiles). A decision
// depends on the photon and on the query's normal and filter settings only, and neighbouring
// pixels on one face share the normal bit for bit and examine mostly the same photons: the
// decision of a photon seen again is read back. Where the normal changes from pixel to pixel
// (smooth shading), the decisions start over but the photon's two unfolded octahedral vectors,
// which depend on the photon only, are read back instead of decoded again. The same decisions,
// so the same photons are found.
#include <cstdint>
#include <cstring>

#include <glm/vec3.hpp>

#include "runtime/photons/photon_map_view.h"

namespace kdpm {

struct FilterMemo {
    static constexpr std::uint32_t kSlots = 2048;  // direct-mapped by photon index
    // Decisions: (generation << 32) | photon, 32 bits of the generation; the current one is never
    // 0 there, so zeroed slots never match.
    std::uint64_t tag[kSlots];
    bool accepted[kSlots];
    std::uint64_t generation = 1;
    // Unfolded direction (0..2) and normal (3..5) of a photon, tagged the same way by
    // vector_generation, which changes with the map or at forget() only.
    std::uint64_t vector_tag[kSlots];
    float unfolded[kSlots][6];
    std::uint64_t vector_generation = 1;
    // What the decisions of the current generation were taken for (null: nothing yet).
    const void* map = nullptr;
    float normal[3] = {0.0f, 0.0f, 0.0f};
    float min_normal_cos = 0.0f;
    std::uint32_t min_bounce = 0, exclude_flags = 0;

    FilterMemo() {
        std::memset(tag, 0, sizeof tag);
        std::memset(vector_tag, 0, sizeof vector_tag);
    }

    // Nothing remembered matches any more (a new tile, a new frame, a map that may have moved).
    void forget() {
        next_decisions();
        next_vectors();
        map = nullptr;
    }

    // Starts a new generation of decisions unless every input of them is the same as before (and
    // of vectors when the map changed).
    void use_for(const PhotonMapView& m, glm::vec3 n, float min_cos, std::uint32_t bounce, std::uint32_t exclude) {
        const float nn[3] = {n.x, n.y, n.z};
        if (map != nullptr && map == m.directions && std::memcmp(nn, normal, sizeof nn) == 0 &&
            min_cos == min_normal_cos && bounce == min_bounce && exclude == exclude_flags)
            return;
        next_decisions();
        if (map != m.directions) next_vectors();
        map = m.directions;
        std::memcpy(normal, nn, sizeof nn);
        min_normal_cos = min_cos;
        min_bounce = bounce;
        exclude_flags = exclude;
    }

    // The filter's decision for photon p (a SurfacePhotonFilter made for use_for's inputs).
    template <class Filter>
    bool decide(std::uint32_t p, const Filter& filter) {
        const std::uint32_t slot = p & (kSlots - 1);
        const std::uint64_t want = (generation << 32) | p;
        if (tag[slot] == want) return accepted[slot];
        bool a;
        if (!filter.quick) {
            a = filter(p);
        } else if (!filter.passes_flags(p)) {
            a = false;
        } else {
            float* u = unfolded[slot];
            const std::uint64_t vectors = (vector_generation << 32) | p;
            if (vector_tag[slot] != vectors) {
                Filter::unfolded(filter.directions[p].direction, u);
                Filter::unfolded(filter.directions[p].normal, u + 3);
                vector_tag[slot] = vectors;
            }
            a = filter.decide_unfolded(p, u, u + 3);
        }
        tag[slot] = want;
        accepted[slot] = a;
        return a;
    }

private:
    // The tags keep 32 bits of a generation: when those wrap, the tags start over.
    void next_decisions() {
        if ((++generation & 0xffffffffu) == 0) {
            std::memset(tag, 0, sizeof tag);
            generation = 1;
        }
    }
    void next_vectors() {
        if ((++vector_generation & 0xffffffffu) == 0) {
            std::memset(vector_tag, 0, sizeof vector_tag);
            vector_generation = 1;
        }
    }
};

// A filter whose decisions go through a FilterMemo.
template <class Filter>
struct MemoizedFilter {
    const Filter* filter;
    FilterMemo* memo;
    bool operator()(std::uint32_t p) const { return memo->decide(p, *filter); }
};

}  // namespace kdpm
