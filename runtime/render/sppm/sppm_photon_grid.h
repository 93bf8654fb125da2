#pragma once
// The photons of one progressive pass in a hashed uniform grid, for the visible points' radius
// queries. Built on the host (a stable counting sort by bucket, so the same photons always give
// the same arrays) and read by the gather kernel on either backend. The grid is over the photons
// rather than over the visible points (pbrt-v4's choice): each pixel then sums its own photons in
// a fixed order with no atomic float adds, so images are identical whatever the thread count or
// the backend schedule.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "formats/host_device.h"
#include "formats/photon_layout.h"

namespace kdpm {

struct SppmPhoton {
    glm::vec3 position;
    glm::vec3 power;   // flux carried, already divided by the photons emitted in the pass
    glm::vec3 normal;  // geometric normal on the side the photon arrived from
    std::int32_t cell[3];  // its grid cell: tells it apart from another cell's photons in the same bucket
};

struct SppmGridView {
    const SppmPhoton* photons = nullptr;      // sorted by bucket
    const std::uint32_t* bucket_start = nullptr;  // bucket_mask + 2 entries
    std::uint32_t bucket_mask = 0;            // bucket count - 1 (a power of two)
    std::uint32_t photon_count = 0;
    glm::vec3 origin{0.0f};                   // corner of cell (0, 0, 0)
    float inv_cell = 1.0f;
    std::int32_t max_cell[3] = {0, 0, 0};     // no photon lies beyond these cells

    KDPM_HD static std::uint32_t bucket_of(std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t mask) {
        return ((static_cast<std::uint32_t>(x) * 73856093u) ^ (static_cast<std::uint32_t>(y) * 19349663u) ^
                (static_cast<std::uint32_t>(z) * 83492791u)) & mask;
    }
    KDPM_HD std::int32_t cell_coordinate(float p, float o) const {
        return static_cast<std::int32_t>(floorf((p - o) * inv_cell));
    }

    // Calls visit(photon) for every photon within sqrt(radius2) of x.
    template <class Visit>
    KDPM_HD void for_each_within(const glm::vec3& x, float radius2, Visit&& visit) const {
        if (photon_count == 0) return;
        const float r = sqrtf(radius2);
        std::int32_t lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = cell_coordinate(x[a] - r, origin[a]);
            hi[a] = cell_coordinate(x[a] + r, origin[a]);
            if (hi[a] < 0 || lo[a] > max_cell[a]) return;
            lo[a] = lo[a] < 0 ? 0 : lo[a];
            hi[a] = hi[a] > max_cell[a] ? max_cell[a] : hi[a];
        }
        for (std::int32_t z = lo[2]; z <= hi[2]; ++z)
            for (std::int32_t y = lo[1]; y <= hi[1]; ++y)
                for (std::int32_t cx = lo[0]; cx <= hi[0]; ++cx) {
                    const std::uint32_t b = bucket_of(cx, y, z, bucket_mask);
                    for (std::uint32_t j = bucket_start[b]; j < bucket_start[b + 1]; ++j) {
                        const SppmPhoton& p = photons[j];
                        if (p.cell[0] != cx || p.cell[1] != y || p.cell[2] != z) continue;
                        const glm::vec3 d = p.position - x;
                        if (d.x * d.x + d.y * d.y + d.z * d.z <= radius2) visit(p);
                    }
                }
    }
};

// Host arrays behind an SppmGridView (the view's pointers are filled by the caller, where the
// arrays live: the host or the device).
struct SppmPhotonGrid {
    std::vector<SppmPhoton> photons;
    std::vector<std::uint32_t> bucket_start;
    SppmGridView view;  // all but the two pointers
};

// The hits with bounce index in [min_bounce, max_bounce], in cells of side `cell` (>= the
// largest query radius, so a query touches at most 2 x 2 x 2 cells). Deterministic.
inline SppmPhotonGrid build_sppm_photon_grid(const std::vector<PhotonHit>& hits, std::uint32_t min_bounce,
                                             std::uint32_t max_bounce, float cell) {
    SppmPhotonGrid grid;
    std::vector<SppmPhoton> kept;
    glm::vec3 lo(3.402823466e38f), hi(-3.402823466e38f);
    for (const PhotonHit& h : hits) {
        const std::uint32_t b = photon_bounce(h.flags);
        if (b < min_bounce || b > max_bounce) continue;
        SppmPhoton p{};
        p.position = glm::vec3(h.position[0], h.position[1], h.position[2]);
        p.power = glm::vec3(h.power[0], h.power[1], h.power[2]);
        p.normal = glm::vec3(h.normal[0], h.normal[1], h.normal[2]);
        lo = glm::min(lo, p.position);
        hi = glm::max(hi, p.position);
        kept.push_back(p);
    }
    SppmGridView& v = grid.view;
    v.photon_count = static_cast<std::uint32_t>(kept.size());
    std::uint32_t buckets = 1;
    while (buckets < kept.size() && buckets < (1u << 30)) buckets <<= 1;
    v.bucket_mask = buckets - 1;
    grid.bucket_start.assign(static_cast<std::size_t>(buckets) + 1, 0u);
    if (kept.empty()) return grid;
    // At most 2^20 cells per axis, so cell coordinates stay far from integer overflow.
    const glm::vec3 extent = hi - lo;
    const float widest = std::max({extent.x, extent.y, extent.z});
    cell = std::max({cell, widest / 1048576.0f, 1e-30f});
    v.origin = lo;
    v.inv_cell = 1.0f / cell;
    for (int a = 0; a < 3; ++a) v.max_cell[a] = v.cell_coordinate(hi[a], lo[a]);
    std::vector<std::uint32_t> bucket(kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i) {
        SppmPhoton& p = kept[i];
        for (int a = 0; a < 3; ++a) p.cell[a] = v.cell_coordinate(p.position[a], lo[a]);
        bucket[i] = SppmGridView::bucket_of(p.cell[0], p.cell[1], p.cell[2], v.bucket_mask);
        ++grid.bucket_start[bucket[i] + 1];
    }
    for (std::uint32_t b = 0; b < buckets; ++b) grid.bucket_start[b + 1] += grid.bucket_start[b];
    std::vector<std::uint32_t> next(grid.bucket_start.begin(), grid.bucket_start.end() - 1);
    grid.photons.resize(kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i) grid.photons[next[bucket[i]]++] = kept[i];
    return grid;
}

}  // namespace kdpm
