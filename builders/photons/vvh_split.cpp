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

void count_vvh_bins(const PhotonRecord* r, std::uint32_t n, const Cell& b, VvhBins& counts) {
    for (int a = 0; a < 3; ++a) {
        const float lo = b.lo[a], extent = b.hi[a] - b.lo[a];
        if (!(extent > 0.0f)) continue;
        const float scale = kBins / extent;
        for (std::uint32_t i = 0; i < n; ++i) {
            int bin = static_cast<int>((r[i].position[a] - lo) * scale);
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

    // grown_volume of the children without building them: per axis the other two factors are
    // fixed, and the product keeps grown_volume's order (axis 0, 1, 2), so the costs are its bits.
    double grown[3];
    for (int a = 0; a < 3; ++a) grown[a] = (static_cast<double>(cell.hi[a]) - cell.lo[a]) + 2.0 * r;
    double best = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
        auto volume_with = [&](double factor) {
            return a == 0 ? (factor * grown[1]) * grown[2] : a == 1 ? (grown[0] * factor) * grown[2] : (grown[0] * grown[1]) * factor;
        };
        auto consider = [&](float s, std::uint32_t below, std::uint32_t above) {
            const double below_volume = volume_with((static_cast<double>(s) - cell.lo[a]) + 2.0 * r);
            const double above_volume = volume_with((static_cast<double>(cell.hi[a]) - s) + 2.0 * r);
            const double cost =
                costs.traverse + (below_volume * below + above_volume * above) / cell_volume * costs.photon;
            if (cost < best) {
                best = cost;
                best_choice = SplitChoice{false, a, s};
            }
        };
        // Empty space between the cell wall and the photons: a query landing there costs nothing.
        if (cell.lo[a] < b.lo[a]) consider(b.lo[a], 0, n);
        float past_top = std::nextafter(b.hi[a], std::numeric_limits<float>::infinity());
        if (past_top < cell.hi[a]) consider(past_top, n, 0);

        const float lo = b.lo[a], extent = b.hi[a] - b.lo[a];
        if (!(extent > 0.0f)) continue;
        std::uint32_t below = 0;
        for (int i = 1; i < kBins; ++i) {
            below += counts[a][i - 1];
            float s = lo + extent * (static_cast<float>(i) / kBins);
            if (s > lo && s <= b.hi[a]) consider(s, below, n - below);
        }
    }
    const double leaf_cost = static_cast<double>(n) * costs.photon;
    if (!std::isfinite(best) || (n <= max_leaf_size && best >= leaf_cost)) return SplitChoice{};
    return best_choice;
}

SplitChoice choose_vvh_split(const PhotonRecord* r, std::uint32_t n, const Cell& cell,
                             float query_radius, std::uint32_t max_leaf_size, const VvhCosts& costs) {
    if (n <= 1) return SplitChoice{};
    const Cell b = photon_bounds(r, n);
    VvhBins counts = {};
    count_vvh_bins(r, n, b, counts);
    return choose_vvh_split_from_bins(b, counts, n, cell, query_radius, max_leaf_size, costs);
}

}  // namespace kdpm::photon_build
