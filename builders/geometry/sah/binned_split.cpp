#include "builders/geometry/sah/binned_split.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "builders/geometry/sah/sah_cost.h"

namespace kdpm {

namespace {

// Fixed chunking keeps the work split independent of the thread count.
constexpr std::size_t kChunk = 8192;

struct Bins {
    std::array<std::array<std::uint32_t, kBins>, 3> starts{}, ends{};
    float lo[3] = {INFINITY, INFINITY, INFINITY};
    float hi[3] = {-INFINITY, -INFINITY, -INFINITY};
};

}  // namespace

BinnedSplit find_binned_split(std::span<const AxisBox> boxes, const AxisBox& cell, const KdBuildParams& params) {
    BinnedSplit best;
    const std::size_t n = boxes.size();
    const float area = box_area(cell);
    if (n == 0 || !(area > 0.0f)) return best;
    float scale[3];
    for (int k = 0; k < 3; ++k) {
        const float extent = cell.hi[k] - cell.lo[k];
        scale[k] = extent > 0.0f ? static_cast<float>(kBins) / extent : 0.0f;
    }
    auto bin = [&](int k, float x) {
        const float f = (x - cell.lo[k]) * scale[k];
        return f <= 0.0f ? 0 : std::min(kBins - 1, static_cast<int>(f));
    };

    const std::size_t chunks = (n + kChunk - 1) / kChunk;
    std::vector<Bins> partial(chunks);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t c = r.begin(); c != r.end(); ++c) {
            Bins& b = partial[c];
            const std::size_t end = std::min(n, (c + 1) * kChunk);
            for (std::size_t i = c * kChunk; i < end; ++i) {
                const AxisBox& box = boxes[i];
                for (int k = 0; k < 3; ++k) {
                    ++b.starts[k][bin(k, box.lo[k])];
                    ++b.ends[k][bin(k, box.hi[k])];
                    // + 0.0f folds -0 into +0, so min/max do not depend on the order.
                    b.lo[k] = std::min(b.lo[k], box.lo[k] + 0.0f);
                    b.hi[k] = std::max(b.hi[k], box.hi[k] + 0.0f);
                }
            }
        }
    });
    Bins total;
    for (const Bins& b : partial)
        for (int k = 0; k < 3; ++k) {
            for (int i = 0; i < kBins; ++i) total.starts[k][i] += b.starts[k][i], total.ends[k][i] += b.ends[k][i];
            total.lo[k] = std::min(total.lo[k], b.lo[k]);
            total.hi[k] = std::max(total.hi[k], b.hi[k]);
        }

    const auto count = static_cast<std::uint32_t>(n);
    float best_cost = params.intersection_cost * static_cast<float>(n);
    auto consider = [&](int k, float pos, std::uint32_t nl, std::uint32_t nr, bool force_side, bool planar_left) {
        if (!(pos > cell.lo[k] && pos < cell.hi[k])) return;
        const SplitCost c = sah_split_cost(params, cell, area, k, pos, nl, 0, nr);
        if (c.cost < best_cost) {
            best_cost = c.cost;
            best = BinnedSplit{k, pos, force_side ? planar_left : c.planar_left};
        }
    };
    for (int k = 0; k < 3; ++k) {
        if (!(cell.hi[k] > cell.lo[k])) continue;
        // Cutting off empty space: planar triangles on the plane go to the non-empty side.
        consider(k, total.lo[k], 0, count, true, false);
        consider(k, total.hi[k], count, 0, true, true);
        std::uint32_t nl = 0, nr = count;
        const float step = (cell.hi[k] - cell.lo[k]) / static_cast<float>(kBins);
        for (int j = 1; j < kBins; ++j) {
            nl += total.starts[k][j - 1];
            nr -= total.ends[k][j - 1];
            consider(k, cell.lo[k] + step * static_cast<float>(j), nl, nr, false, true);
        }
    }
    return best;
}

}  // namespace kdpm
