#pragma once
// CPU photon shooting one ray at a time over all the live paths of a batch ("waves"), each
// wave's rays sorted by where they start and where they go. Traced one path after another,
// consecutive rays start anywhere and walk different parts of the kd-tree, so nearly every node
// step waits on memory; sorted, neighbouring rays walk the same nodes (one thread, Sponza's
// 481,430 bounce rays: 0.54x the time of the same rays shuffled). A path is a pure function of
// its index (photon_path.h) and each wave moves every path by exactly one step, so the hits are
// those of trace_photon_path, whatever the order, batch size or thread count.
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

// One ray of each path, in ray order: the stored photon (if any) to wave_hits[j] with
// stored[j] = 1; if the path goes on, sorted[j] is its next state and next[j] its rank in the
// next wave, else next[j].key = kWaveEnded. Nothing is written where the path's
// slots are: stores scattered among the walk's loads cost it more than the separate pass below
// (Sponza, two threads, separate lab runs: 284 against 255-267 ms). Ranking here, while the state
// is at hand, leaves 8-byte ranks to compact between waves instead of 56-byte states.
inline constexpr std::uint32_t kWaveEnded = ~0u;  // above every WaveKey (30 bits)
template <class ClosestHit>
struct WaveStepPass {
    GeometryView geometry;
    ShootSettings settings;
    WaveKey key;
    PhotonPathState* sorted = nullptr;
    PhotonHit* wave_hits = nullptr;
    std::uint8_t* stored = nullptr;
    WaveRank* next = nullptr;
    ClosestHit intersect{};
    void operator()(std::uint64_t j) const {
        PhotonPathState& st = sorted[j];
        const Hit hit = intersect(geometry, next_photon_ray(st));
        bool stores = false;
        const bool goes_on = continue_photon_path(geometry, settings, hit, st, &wave_hits[j], stores);
        st.stored = static_cast<std::uint16_t>(st.stored + (stores ? 1 : 0));
        stored[j] = stores ? 1 : 0;
        next[j] = WaveRank{goes_on ? key(st) : kWaveEnded, static_cast<std::uint32_t>(j)};
    }
};

// The wave's photons to their paths' next slots (a path has one ray per wave, so its photons
// arrive in the order trace_photon_path stores them), and the result of each path that ended.
struct WaveStorePass {
    std::uint64_t first = 0;
    std::uint64_t per_path = 0;
    const PhotonPathState* sorted = nullptr;
    const PhotonHit* wave_hits = nullptr;
    const std::uint8_t* stored = nullptr;
    const WaveRank* next = nullptr;
    PhotonHit* slots = nullptr;
    PhotonPathResult* results = nullptr;
    void operator()(std::uint64_t j) const {
        const PhotonPathState& st = sorted[j];
        const std::uint64_t i = st.path - first;
        if (stored[j]) slots[i * per_path + st.stored - 1] = wave_hits[j];
        // An ended path's bounce is that of its last ray: one ray per bounce 0..bounce.
        if (next[j].key == kWaveEnded) results[i] = PhotonPathResult{st.stored, st.bounce + 1};
    }
};

}  // namespace shoot_waves_detail

// Paths first .. first + n - 1 into slots (max_bounces + 1 per path) and results, as n work
// items of ShootPathsPass would write them. `dev` runs the passes (a CpuDevice).
template <class Device, class ClosestHit>
void shoot_batch_in_waves(Device& dev, const GeometryView& geometry, const LightSelection& lights,
                          const ShootSettings& settings, std::uint64_t first, std::uint64_t n, PhotonHit* slots,
                          PhotonPathResult* results, const ClosestHit& intersect) {
    using namespace shoot_waves_detail;
    static_assert(Device::arrays_on_host, "waves sort and compact on the host");
    static_assert(std::is_trivial_v<PhotonPathState> && std::is_trivial_v<PhotonHit>, "scratch arrays stay uncleared");
    if (!photons_can_start(lights, settings)) {
        for (std::uint64_t i = 0; i < n; ++i) results[i] = PhotonPathResult{};  // as trace_photon_path
        return;
    }
    // Written before they are read, so not cleared. Each wave reads the states of the one before
    // from one array and steps them in the other.
    auto states_a = dev.template scratch<PhotonPathState>(n);
    auto states_b = dev.template scratch<PhotonPathState>(n);
    auto wave_hits = dev.template scratch<PhotonHit>(n);
    auto stored = dev.template scratch<std::uint8_t>(n);
    auto next = dev.template scratch<WaveRank>(n);
    PhotonPathState* previous = states_a.data();
    PhotonPathState* sorted = states_b.data();
    std::vector<WaveRank> ranks(n);
    const WaveKey key(geometry.info);
    dev.launch(n, WaveStartPass{geometry, lights, settings, first, previous});
    dev.launch(n, WaveKeyPass{key, previous, ranks.data()});
    for (std::uint64_t m = n; m > 0;) {
        // Stable: equal keys keep the previous wave's order, so the order is the same every run.
        stable_radix_sort(ranks, [](const WaveRank& r) { return static_cast<std::uint64_t>(r.key); });
        dev.launch(m, WaveGatherPass{previous, ranks.data(), sorted});
        dev.launch(m, WaveStepPass<ClosestHit>{geometry, settings, key, sorted, wave_hits.data(), stored.data(),
                                               next.data(), intersect});
        dev.launch(m, WaveStorePass{first, settings.max_bounces + std::uint64_t{1}, sorted, wave_hits.data(),
                                    stored.data(), next.data(), slots, results});
        std::uint64_t going_on = 0;
        const WaveRank* stepped = next.data();
        for (std::uint64_t j = 0; j < m; ++j)
            if (stepped[j].key != kWaveEnded) ranks[going_on++] = stepped[j];
        ranks.resize(going_on);
        m = going_on;
        std::swap(previous, sorted);
    }
}

}  // namespace kdpm
