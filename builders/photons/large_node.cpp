#include "builders/photons/large_node.h"

#include <algorithm>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace kdpm::photon_build {
namespace {

constexpr std::uint32_t kChunk = 16384;

template <class Body>
void for_each_chunk(std::uint32_t n, Body&& body) {
    const std::uint32_t chunks = (n + kChunk - 1) / kChunk;
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, chunks, 1), [&](const tbb::blocked_range<std::uint32_t>& r) {
        for (std::uint32_t c = r.begin(); c != r.end(); ++c) body(c, c * kChunk, std::min(n, (c + 1) * kChunk));
    });
}

}  // namespace

Cell parallel_photon_bounds(const PhotonRecord* r, std::uint32_t n) {
    if (n == 0) return photon_bounds(r, n);
    std::vector<Cell> part((n + kChunk - 1) / kChunk);
    for_each_chunk(n, [&](std::uint32_t c, std::uint32_t begin, std::uint32_t end) {
        part[c] = photon_bounds(r + begin, end - begin);
    });
    // std::min/max keep the earlier of equal values (+0 and -0), as the sequential scan does.
    Cell b = part[0];
    for (std::size_t c = 1; c < part.size(); ++c)
        for (int a = 0; a < 3; ++a) {
            b.lo[a] = std::min(b.lo[a], part[c].lo[a]);
            b.hi[a] = std::max(b.hi[a], part[c].hi[a]);
        }
    return b;
}

SplitChoice parallel_vvh_split(const PhotonRecord* r, std::uint32_t n, const Cell& cell, float query_radius,
                               std::uint32_t max_leaf_size, const VvhCosts& costs) {
    if (n <= 1) return SplitChoice{};
    const Cell b = parallel_photon_bounds(r, n);
    struct Bins {
        VvhBins counts = {};
    };
    std::vector<Bins> part((n + kChunk - 1) / kChunk);
    for_each_chunk(n, [&](std::uint32_t c, std::uint32_t begin, std::uint32_t end) {
        count_vvh_bins(r + begin, end - begin, b, part[c].counts);
    });
    VvhBins counts = {};
    for (const Bins& bins : part)
        for (int a = 0; a < 3; ++a)
            for (int i = 0; i < kVvhBins; ++i) counts[a][i] += bins.counts[a][i];
    return choose_vvh_split_from_bins(b, counts, n, cell, query_radius, max_leaf_size, costs);
}

std::uint32_t parallel_stable_partition(PhotonRecord* r, std::uint32_t n, int axis, float position) {
    const std::uint32_t chunks = (n + kChunk - 1) / kChunk;
    std::vector<std::uint32_t> below(chunks + 1, 0), above(chunks + 1, 0);
    for_each_chunk(n, [&](std::uint32_t k, std::uint32_t begin, std::uint32_t end) {
        std::uint32_t m = 0;
        for (std::uint32_t i = begin; i < end; ++i) m += r[i].position[axis] < position;
        below[k + 1] = m;
        above[k + 1] = (end - begin) - m;
    });
    for (std::uint32_t k = 0; k < chunks; ++k) below[k + 1] += below[k], above[k + 1] += above[k];
    const std::uint32_t total_below = below[chunks];
    std::vector<PhotonRecord> out(n);
    for_each_chunk(n, [&](std::uint32_t k, std::uint32_t begin, std::uint32_t end) {
        std::uint32_t lo = below[k], hi = total_below + above[k];
        for (std::uint32_t i = begin; i < end; ++i) {
            if (r[i].position[axis] < position) out[lo++] = r[i];
            else out[hi++] = r[i];
        }
    });
    for_each_chunk(n, [&](std::uint32_t, std::uint32_t begin, std::uint32_t end) {
        std::copy(out.begin() + begin, out.begin() + end, r + begin);
    });
    return total_below;
}

}  // namespace kdpm::photon_build
