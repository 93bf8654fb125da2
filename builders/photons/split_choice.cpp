#include "builders/photons/split_choice.h"

#include <algorithm>

namespace kdpm::photon_build {

Cell photon_bounds(const Positions& p, const std::uint32_t* idx, std::uint32_t n) {
    Cell c{};
    for (int a = 0; a < 3; ++a) {
        if (n == 0) continue;
        float lo = p.axis[a][idx[0]], hi = lo;
        for (std::uint32_t i = 1; i < n; ++i) {
            float v = p.axis[a][idx[i]];
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        c.lo[a] = lo;
        c.hi[a] = hi;
    }
    return c;
}

}  // namespace kdpm::photon_build
