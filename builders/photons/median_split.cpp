#include "builders/photons/median_split.h"

#include <algorithm>
#include <array>

namespace kdpm::photon_build {

SplitChoice choose_median_split(PhotonRecord* r, std::uint32_t n, std::uint32_t leaf_size) {
    SplitChoice leaf;
    if (n <= leaf_size || n < 2) return leaf;
    Cell b = photon_bounds(r, n);
    std::array<int, 3> axes{0, 1, 2};
    std::stable_sort(axes.begin(), axes.end(),
                     [&](int l, int r) { return b.hi[l] - b.lo[l] > b.hi[r] - b.lo[r]; });
    for (int a : axes) {
        if (!(b.hi[a] > b.lo[a])) continue;
        std::uint32_t mid = n / 2;
        // Ties broken by index so the selection is a function of the data alone.
        std::nth_element(r, r + mid, r + n, [&](const PhotonRecord& x, const PhotonRecord& y) {
            return x.position[a] < y.position[a] || (x.position[a] == y.position[a] && x.index < y.index);
        });
        float m = r[mid].position[a];
        if (m <= b.lo[a]) {
            // The lower half is all one value: split just above it instead.
            float next = b.hi[a];
            for (std::uint32_t i = 0; i < n; ++i)
                if (r[i].position[a] > m) next = std::min(next, r[i].position[a]);
            m = next;
        }
        return SplitChoice{false, a, m};
    }
    return leaf;  // every photon at one point
}

}  // namespace kdpm::photon_build
