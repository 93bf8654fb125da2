#pragma once
// Surface filter decisions remembered across k-nearest searches (the CPU gather's tiles). A
// decision depends on the photon and on the query's normal and filter settings only, and
// neighbouring pixels on one face share the normal bit for bit and examine mostly the same
// photons: the decision of a photon seen again is read back instead of decoding its two
// directions again. The same decisions, so the same photons are found.
#include <cstdint>
#include <cstring>

#include <glm/vec3.hpp>

#include "runtime/photons/photon_map_view.h"

namespace kdpm {

struct FilterMemo {
    static constexpr std::uint32_t kSlots = 2048;  // direct-mapped by photon index
    // (generation << 32) | photon, 32 bits of the generation; the current one is never 0 there, so
    // zeroed slots never match.
    std::uint64_t tag[kSlots];
    bool accepted[kSlots];
    std::uint64_t generation = 1;
    // What the decisions of the current generation were taken for (null: nothing yet).
    const void* map = nullptr;
    float normal[3] = {0.0f, 0.0f, 0.0f};
    float min_normal_cos = 0.0f;
    std::uint32_t min_bounce = 0, exclude_flags = 0;

    FilterMemo() { std::memset(tag, 0, sizeof tag); }

    // Nothing remembered matches any more (a new tile, a new frame, a map that may have moved).
    void forget() {
        ++generation;
        if ((generation & 0xffffffffu) == 0) {  // the tag keeps 32 bits of it: start over
            std::memset(tag, 0, sizeof tag);
            generation = 1;
        }
        map = nullptr;
    }

    // Starts a new generation unless every input of the decisions is the same as before.
    void use_for(const PhotonMapView& m, glm::vec3 n, float min_cos, std::uint32_t bounce, std::uint32_t exclude) {
        const float nn[3] = {n.x, n.y, n.z};
        if (map != nullptr && map == m.directions && std::memcmp(nn, normal, sizeof nn) == 0 &&
            min_cos == min_normal_cos && bounce == min_bounce && exclude == exclude_flags)
            return;
        forget();
        map = m.directions;
        std::memcpy(normal, nn, sizeof nn);
        min_normal_cos = min_cos;
        min_bounce = bounce;
        exclude_flags = exclude;
    }

    template <class Filter>
    bool decide(std::uint32_t p, const Filter& filter) {
        const std::uint32_t slot = p & (kSlots - 1);
        const std::uint64_t want = (generation << 32) | p;
        if (tag[slot] == want) return accepted[slot];
        const bool a = filter(p);
        tag[slot] = want;
        accepted[slot] = a;
        return a;
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
