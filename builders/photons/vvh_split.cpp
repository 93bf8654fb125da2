#include "builders/photons/vvh_split.h"

#include <cmath>
#include <limits>

namespace kdpm::photon_build {
namespace {

constexpr int kBins = kVvhBins;

double grown_volume(const float lo[3], const float hi[3], double r) {
    double v = 1.0;
    for (int a = 0; a < 3; ++a) v *= (static_cast<double>(hi[a]) - lo[a]) + 2.0 * r;
    return v;
}

}  // namespace

void count_vvh_bins(const Positions& p, const std::uint32_t* idx, std::uint32_t n, const Cell& b, VvhBins& counts) {
    for (int a = 0; a < 3; ++a) {
        const float lo = b.lo[a], extent = b.hi[a] - b.lo[a];
        if (!(extent > 0.0f)) continue;
        const float* c = p.axis[a];
        const float scale = kBins / extent;
        for (std::uint32_t i = 0; i < n; ++i) {
            int bin = static_cast<int>((c[idx[i]] - lo) * scale);
            counts[a][bin < 0 ? 0 : (bin >= kBins ? kBins - 1 : bin)]++;
        }
    }
}

SplitChoice choose_vvh_split_from_bins(const Cell& b, const VvhBins& counts, std::uint32_t n, const Cell& cell,
                                       float query_radius, std::uint32_t max_leaf_size, const VvhCosts& costs) {
    SplitChoice best_choice;
    if (n <= 1) return best_choice;
    const double r = query_radius;
    const double cell_volume = grown_volume(cell.lo, cell.hi, r);
    if (!(cell_volume > 0.0) || !std::isfinite(cell_volume)) return best_choice;

    double best = std::numeric_limits<double>::infinity();
    auto consider = [&](int a, float s, std::uint32_t below, std::uint32_t above) {
        Cell lo_cell = cell, hi_cell = cell;
        lo_cell.hi[a] = s;
        hi_cell.lo[a] = s;
        double cost = costs.traverse + (grown_volume(lo_cell.lo, lo_cell.hi, r) * below +
                                        grown_volume(hi_cell.lo, hi_cell.hi, r) * above) /
                                           cell_volume * costs.photon;
        if (cost < best) {
            best = cost;
            best_choice = SplitChoice{false, a, s};
        }
    };

    for (int a = 0; a < 3; ++a) {
        // Empty space between the cell wall and the photons: a query landing there costs nothing.
        if (cell.lo[a] < b.lo[a]) consider(a, b.lo[a], 0, n);
        float past_top = std::nextafter(b.hi[a], std::numeric_limits<float>::infinity());
        if (past_top < cell.hi[a]) consider(a, past_top, n, 0);

        const float lo = b.lo[a], extent = b.hi[a] - b.lo[a];
        if (!(extent > 0.0f)) continue;
        std::uint32_t below = 0;
        for (int i = 1; i < kBins; ++i) {
            below += counts[a][i - 1];
            float s = lo + extent * (static_cast<float>(i) / kBins);
            if (s > lo && s <= b.hi[a]) consider(a, s, below, n - below);
        }
    }
    const double leaf_cost = static_cast<double>(n) * costs.photon;
    if (!std::isfinite(best) || (n <= max_leaf_size && best >= leaf_cost)) return SplitChoice{};
    return best_choice;
}

SplitChoice choose_vvh_split(const Positions& p, const std::uint32_t* idx, std::uint32_t n, const Cell& cell,
                             float query_radius, std::uint32_t max_leaf_size, const VvhCosts& costs) {
    if (n <= 1) return SplitChoice{};
    const Cell b = photon_bounds(p, idx, n);
    VvhBins counts = {};
    count_vvh_bins(p, idx, n, b, counts);
    return choose_vvh_split_from_bins(b, counts, n, cell, query_radius, max_leaf_size, costs);
}

}  // namespace kdpm::photon_build
