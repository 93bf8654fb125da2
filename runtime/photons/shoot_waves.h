#pragma once
// CPU photon shooting one ray at a time over all the live paths of a batch ("waves"), each
// wave's rays sorted by where they start and where they go. Traced one path after another,
// consecutive rays start anywhere and walk different parts of the kd-tree, so nearly every node
// step waits on memory; sorted, neighbouring rays walk the same nodes, which are then in cache.
// A path is a pure function of its index (photon_path.h) and each wave moves every path by
// exactly one step, so the hits are those of trace_photon_path, whatever the order, batch size
// or thread count.
// Host memory only (CpuDevice): the sort and the compaction run on the calling thread.
#include <array>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "formats/photon_layout.h"
#include "formats/stable_radix_sort.h"
#include "runtime/geometry/geometry_view.h"
#include "runtime/photons/photon_path.h"
#include "runtime/shading/area_light.h"

namespace kdpm {

namespace shoot_waves_detail {

// A live path's place in a wave: its sort key and its slot in the wave's state array.
struct WaveRank {
    std::uint32_t key;
    std::uint32_t slot;
};

// 30 bits: 5 of each coordinate of the origin (within the scene bounds) and of the direction,
// interleaved from the most significant down, so that rays close in both come out together.
struct WaveKey {
    glm::vec3 low{0.0f}, scale{0.0f};  // origin cell = (origin - low) * scale, in [0, 32)

    explicit WaveKey(const GeometryInfo& info) {
        for (int a = 0; a < 3; ++a) {
            const float extent = info.bounds_max[a] - info.bounds_min[a];
            low[a] = info.bounds_min[a];
            scale[a] = extent > 0.0f ? 32.0f / extent : 0.0f;
        }
    }
    // 0..31; NaN and values outside go to the nearest end.
    static std::uint32_t cell(float f) { return f > 0.0f ? (f < 31.0f ? static_cast<std::uint32_t>(f) : 31u) : 0u; }
    // Bit b of a cell moved to bit 6b: six such spreads, shifted by 5..0, interleave the cells.
    static constexpr std::uint32_t spread(std::uint32_t c) {
        std::uint32_t out = 0;
        for (std::uint32_t b = 0; b < 5; ++b) out |= ((c >> b) & 1u) << (6 * b);
        return out;
    }
    std::uint32_t operator()(const PhotonPathState& st) const {
        static constexpr auto kSpread = [] {
            std::array<std::uint32_t, 32> t{};
            for (std::uint32_t c = 0; c < 32; ++c) t[c] = spread(c);
            return t;
        }();
        return kSpread[cell((st.origin.x - low.x) * scale.x)] << 5 | kSpread[cell((st.origin.y - low.y) * scale.y)] << 4 |
               kSpread[cell((st.origin.z - low.z) * scale.z)] << 3 | kSpread[cell((st.direction.x + 1.0f) * 16.0f)] << 2 |
               kSpread[cell((st.direction.y + 1.0f) * 16.0f)] << 1 | kSpread[cell((st.direction.z + 1.0f) * 16.0f)];
    }
};

struct WaveStartPass {
    GeometryView geometry;
    LightSelection lights;
    ShootSettings settings;
    std::uint64_t first = 0;
    PhotonPathState* live = nullptr;
    void operator()(std::uint64_t i) const { live[i] = start_photon_path(geometry, lights, settings, first + i); }
};

// The first wave's ranks (later waves' come from the step pass).
struct WaveKeyPass {
    WaveKey key;
    const PhotonPathState* live = nullptr;
    WaveRank* ranks = nullptr;
    void operator()(std::uint64_t j) const { ranks[j] = WaveRank{key(live[j]), static_cast<std::uint32_t>(j)}; }
};

// The wave's states in ray order, read apart from the walk so that its scattered loads do not
// interleave with the tree's: from the previous wave's array (slot = its index there).
struct WaveGatherPass {
    const PhotonPathState* previous = nullptr;
    const WaveRank* ranks = nullptr;
    PhotonPathState* sorted = nullptr;
    void operator()(std::uint64_t j) const { sorted[j] = previous[ranks[j].slot]; }
};

// Where a wave's ray stored its photon: the path's place in the batch and the photon's index
// among the path's stored ones, packed by wave_place (a path stores at most kWaveMaxBounces + 1,
// so the index fits kWaveIndexBits), or kWaveNotStored.
inline constexpr std::uint32_t kWaveNotStored = ~0u;
inline constexpr std::uint32_t kWaveIndexBits = 8;
inline constexpr std::uint32_t kWaveIndexMask = (1u << kWaveIndexBits) - 1;
// A path stores at most max_bounces + 1 photons, so their indices fit the index bits.
inline constexpr std::uint32_t kWaveMaxBounces = kWaveIndexMask;
// Places pack below kWaveNotStored.
inline constexpr std::uint64_t kWaveMaxBatch = (std::uint64_t{1} << (32 - kWaveIndexBits)) - 1;
constexpr std::uint32_t wave_place(std::uint32_t place, std::uint32_t index) { return place << kWaveIndexBits | index; }

// One ray of each path, in ray order: the stored photon (if any) to wave_hits[j] and its place in
// the shot to where[j]; if the path goes on, sorted[j] is its next state and next[j] its rank in
// the next wave, else next[j].key = kWaveEnded and the path's result is written. The photons stay
// in wave order until the batch ends (WavePlacePass), where each is copied once, straight to its
// place in the shot: scattered to per-path slots in a pass after the walk and the slots compacted
// on one thread, they would add a large share to the walk's time. Ranking here, while the state
// is at hand, leaves 8-byte ranks to compact between waves instead of 56-byte states.
inline constexpr std::uint32_t kWaveEnded = ~0u;  // above every WaveKey (30 bits)
template <class ClosestHit>
struct WaveStepPass {
    GeometryView geometry;
    ShootSettings settings;
    WaveKey key;
    std::uint64_t first = 0;
    PhotonPathState* sorted = nullptr;
    PhotonHit* wave_hits = nullptr;
    std::uint32_t* where = nullptr;
    WaveRank* next = nullptr;
    PhotonPathResult* results = nullptr;
    ClosestHit intersect{};
    void operator()(std::uint64_t j) const {
        PhotonPathState& st = sorted[j];
        const Hit hit = intersect(geometry, next_photon_ray(st));
        bool stores = false;
        const bool goes_on = continue_photon_path(geometry, settings, hit, st, &wave_hits[j], stores);
        const auto place = static_cast<std::uint32_t>(st.path - first);
        where[j] = stores ? wave_place(place, st.stored) : kWaveNotStored;
        st.stored = static_cast<std::uint16_t>(st.stored + (stores ? 1 : 0));
        if (goes_on) {
            next[j] = WaveRank{key(st), static_cast<std::uint32_t>(j)};
        } else {
            next[j] = WaveRank{kWaveEnded, static_cast<std::uint32_t>(j)};
            // An ended path's bounce is that of its last ray: one ray per bounce 0..bounce.
            results[place] = PhotonPathResult{st.stored, st.bounce + 1};
        }
    }
};

// Every photon of the batch's waves to its place in `out`: the path's first (path_start, by
// place) plus its index, so the shot holds them in path order, each path's in the order
// trace_photon_path stores them (a path has one ray per wave).
struct WavePlacePass {
    const PhotonHit* wave_hits = nullptr;
    const std::uint32_t* where = nullptr;
    const std::uint64_t* path_start = nullptr;
    PhotonHit* out = nullptr;
    void operator()(std::uint64_t e) const {
        const std::uint32_t w = where[e];
        if (w != kWaveNotStored) out[path_start[w >> kWaveIndexBits] + (w & kWaveIndexMask)] = wave_hits[e];
    }
};

}  // namespace shoot_waves_detail

// Paths first .. first + n - 1 (n <= kWaveMaxBatch, max_bounces <= kWaveMaxBounces), as n work
// items of ShootPathsPass would trace them: each path's result to results[i] and the batch's
// photons appended to `hits` in path order, after reserve(photons of the batch) has had its say on
// hits' capacity. `dev` runs the passes (a CpuDevice).
template <class Device, class ClosestHit, class Reserve>
void shoot_batch_in_waves(Device& dev, const GeometryView& geometry, const LightSelection& lights,
                          const ShootSettings& settings, std::uint64_t first, std::uint64_t n,
                          PhotonPathResult* results, std::vector<PhotonHit>& hits, const Reserve& reserve,
                          const ClosestHit& intersect) {
    using namespace shoot_waves_detail;
    static_assert(Device::arrays_on_host, "waves sort and compact on the host");
    static_assert(std::is_trivial_v<PhotonPathState> && std::is_trivial_v<PhotonHit>, "scratch arrays stay uncleared");
    if (!photons_can_start(lights, settings)) {
        for (std::uint64_t i = 0; i < n; ++i) results[i] = PhotonPathResult{};  // as trace_photon_path
        return;
    }
    const std::uint64_t per_path = settings.max_bounces + std::uint64_t{1};
    // Written before they are read, so not cleared. Each wave reads the states of the one before
    // from one array and steps them in the other; its photons and their places follow those of
    // the waves before (a path has at most per_path rays). Pages past the batch's rays are never
    // touched.
    auto states_a = dev.template scratch<PhotonPathState>(n);
    auto states_b = dev.template scratch<PhotonPathState>(n);
    auto wave_hits = dev.template scratch<PhotonHit>(n * per_path);
    auto where = dev.template scratch<std::uint32_t>(n * per_path);
    auto next = dev.template scratch<WaveRank>(n);
    PhotonPathState* previous = states_a.data();
    PhotonPathState* sorted = states_b.data();
    std::vector<WaveRank> ranks(n);
    const WaveKey key(geometry.info);
    dev.launch(n, WaveStartPass{geometry, lights, settings, first, previous});
    dev.launch(n, WaveKeyPass{key, previous, ranks.data()});
    std::uint64_t rays = 0;  // of the waves so far: where this wave's photons go
    for (std::uint64_t m = n; m > 0;) {
        // Stable: equal keys keep the previous wave's order, so the order is the same every run.
        stable_radix_sort(ranks, [](const WaveRank& r) { return static_cast<std::uint64_t>(r.key); });
        dev.launch(m, WaveGatherPass{previous, ranks.data(), sorted});
        dev.launch(m, WaveStepPass<ClosestHit>{geometry, settings, key, first, sorted, wave_hits.data() + rays,
                                               where.data() + rays, next.data(), results, intersect});
        rays += m;
        std::uint64_t going_on = 0;
        const WaveRank* stepped = next.data();
        for (std::uint64_t j = 0; j < m; ++j)
            if (stepped[j].key != kWaveEnded) ranks[going_on++] = stepped[j];
        ranks.resize(going_on);
        m = going_on;
        std::swap(previous, sorted);
    }
    // Each path's first place in `hits`, then every photon copied once to its place.
    std::vector<std::uint64_t> path_start(n);
    std::uint64_t end = hits.size();
    for (std::uint64_t i = 0; i < n; ++i) {
        path_start[i] = end;
        end += results[i].stored;
    }
    reserve(end - hits.size());
    hits.resize(end);
    dev.launch(rays, WavePlacePass{wave_hits.data(), where.data(), path_start.data(), hits.data()});
}

}  // namespace kdpm
